#include "sim/camera_kind.h"

#include <stdexcept>

namespace cosim {

CameraKind cameraKind(const std::string& name) {
  if (const auto kind = choiceNamed(kCameraNames, name)) return *kind;
  throw std::invalid_argument("unknown camera '" + name + "' (" + cameraNames() + ")");
}

const char* cameraName(CameraKind kind) {
  return choiceName(kCameraNames, kind);
}

const char* cameraNames() {
  static const std::string names = [] {
    std::string list;
    for (std::size_t i = 0; i < kCameraNames.size(); ++i)
      list += std::string(i == 0                         ? ""
                          : i + 1 == kCameraNames.size() ? " or "
                                                         : ", ") +
              kCameraNames[i].name;
    return list;
  }();
  return names.c_str();
}

}  // namespace cosim
