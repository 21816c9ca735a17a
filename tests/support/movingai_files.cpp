#include "tests/support/movingai_files.h"

#include <filesystem>

namespace cosim::test {

std::string movingAIFile(const std::string& name) {
  const std::string bundled = std::string(COSIM_SOURCE_DIR) + "/experiments/maps/" + name;
  if (std::filesystem::exists(bundled)) return bundled;
  return std::string(COSIM_SOURCE_DIR) + "/tests/data/movingai/" + name;
}

}  // namespace cosim::test
