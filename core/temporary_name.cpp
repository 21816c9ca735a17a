#include "core/temporary_name.h"

#include <unistd.h>

namespace cosim {

namespace {
constexpr std::size_t kMaxNameBytes = 255;  // NAME_MAX of Linux file systems
}  // namespace

std::filesystem::path temporaryNameFor(const std::filesystem::path& target,
                                       const std::string& tag) {
  const std::string suffix = tag + std::to_string(::getpid());
  std::string name = target.filename().string();
  const std::size_t room = kMaxNameBytes - 1 - suffix.size();  // 1: the leading '.'
  if (name.size() > room) name.resize(room);
  std::string tmp = ".";  // piece by piece: GCC 12's -Wrestrict misfires on operator+ chains
  tmp += name;
  tmp += suffix;
  return target.parent_path() / tmp;
}

}  // namespace cosim
