#include "sim/camera_kind.h"

#include <stdexcept>

namespace cosim {

CameraKind cameraKind(const std::string& name) {
  for (const CameraKind kind : {CameraKind::Chase, CameraKind::Orbit, CameraKind::Top,
                                CameraKind::Overview, CameraKind::Fixed})
    if (name == cameraName(kind)) return kind;
  throw std::invalid_argument("unknown camera '" + name + "' (" + cameraNames() + ")");
}

const char* cameraName(CameraKind kind) {
  switch (kind) {
    case CameraKind::Chase:
      return "chase";
    case CameraKind::Orbit:
      return "orbit";
    case CameraKind::Top:
      return "top";
    case CameraKind::Overview:
      return "overview";
    case CameraKind::Fixed:
      return "fixed";
  }
  return "chase";
}

const char* cameraNames() {
  return "chase, orbit, top, overview or fixed";
}

}  // namespace cosim
