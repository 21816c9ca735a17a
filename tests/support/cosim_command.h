#pragma once
// Runs the built cosim program (COSIM_BINARY, defined for every test program) for end-to-end
// tests.
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "tests/support/test_files.h"

namespace cosim::test {

struct CommandResult {
  int status = -1;
  std::string out, err;
};

// Runs `cosim <args>` with stdout and stderr captured; in folder `cwd` if one is given; killed
// after `timeout_s` seconds if that is positive (status 124 if it then ended on SIGTERM, 137 if
// it had to be killed).
inline CommandResult runCosim(const std::string& args, const std::filesystem::path& cwd = {},
                              int timeout_s = 0) {
  static int counter = 0;
  const auto dir = std::filesystem::temp_directory_path() /
                   ("cosim-test-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
  std::filesystem::create_directories(dir);
  const std::string cd = cwd.empty() ? "" : "cd '" + cwd.string() + "' && ";
  const std::string watchdog =
      timeout_s > 0 ? "timeout -k 5 " + std::to_string(timeout_s) + " " : std::string();
  const std::string cmd = cd + watchdog + std::string(COSIM_BINARY) + " " + args + " >" +
                          (dir / "out").string() + " 2>" + (dir / "err").string();
  const int raw = std::system(cmd.c_str());
  CommandResult r;
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  r.out = slurp(dir / "out");
  r.err = slurp(dir / "err");
  std::filesystem::remove_all(dir);
  return r;
}

}  // namespace cosim::test
