#include "sim/mujoco_messages.h"

#include <mujoco/mujoco.h>

#include <cstdio>
#include <cstdlib>
#include <string>

#include "core/input_error.h"

namespace cosim {

namespace {

// One line: trailing newlines dropped, control characters escaped.
std::string oneLine(const char* text) {
  std::string s = text ? text : "";
  while (!s.empty() && (s.back() == '\n' || s.back() == '\r' || s.back() == ' ')) s.pop_back();
  return printableText(s);
}

extern "C" void onMujocoWarning(const char* text) {
  std::fprintf(stderr, "cosim: mujoco: %s\n", oneLine(text).c_str());
}

// MuJoCo assumes its error handler does not return (MuJoCo 2.2 API reference, mju_user_error).
// Unwinding through MuJoCo's C frames is not an option either, so the process ends here, without
// running destructors on state MuJoCo left half-done.
extern "C" [[noreturn]] void onMujocoError(const char* text) {
  std::fflush(stdout);
  std::fprintf(stderr, "cosim: internal error: mujoco: %s\n", oneLine(text).c_str());
  std::_Exit(3);
}

}  // namespace

void installMujocoMessageHandlers() {
  if (!mju_user_warning) mju_user_warning = onMujocoWarning;
  if (!mju_user_error) mju_user_error = onMujocoError;
}

}  // namespace cosim
