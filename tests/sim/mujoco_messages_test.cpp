// MuJoCo's warning and error handlers: one stderr line each; an error ends the process with the
// internal-error status 3 (MuJoCo cannot continue after one), not MuJoCo's silent exit(1).
#include "sim/mujoco_messages.h"

#include <gtest/gtest.h>
#include <mujoco/mujoco.h>

namespace cosim {
namespace {

// Starts from MuJoCo's defaults (another test may have left its own handler installed).
void installFresh() {
  mju_user_warning = nullptr;
  mju_user_error = nullptr;
  installMujocoMessageHandlers();
}

TEST(MujocoMessages, AWarningIsOneEscapedStderrLine) {
  installFresh();
  testing::internal::CaptureStderr();
  mju_warning("bad value\x01 here\n");
  EXPECT_EQ(testing::internal::GetCapturedStderr(), "cosim: mujoco: bad value\\x01 here\n");
}

TEST(MujocoMessages, AnInstalledHandlerIsKept) {
  mju_user_warning = nullptr;
  static int calls = 0;
  mju_user_warning = [](const char*) { ++calls; };
  installMujocoMessageHandlers();
  mju_warning("x");
  EXPECT_EQ(calls, 1);
  installFresh();
}

TEST(MujocoMessagesDeathTest, AnErrorExitsWithStatusThreeAndSaysSo) {
  installFresh();
  EXPECT_EXIT(mju_error("mj_stackAlloc: insufficient memory"), testing::ExitedWithCode(3),
              "cosim: internal error: mujoco: mj_stackAlloc: insufficient memory");
}

}  // namespace
}  // namespace cosim
