#include "tests/support/test_files.h"

#include <unistd.h>

#include <fstream>
#include <sstream>

namespace cosim::test {

std::string slurp(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::filesystem::path freshDir(const std::string& name) {
  const auto dir =
      std::filesystem::temp_directory_path() / ("cosim-" + name + "-" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  return dir;
}

std::filesystem::path makeFreshDir(const std::string& name) {
  const auto dir = freshDir(name);
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace cosim::test
