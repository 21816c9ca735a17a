#pragma once
// The views a run's pictures and videos are rendered from (the scenario's render.camera and
// render.cameras, `cosim render --camera`): chase (follows the first vehicle), orbit (circles
// the world), top (straight down, nearly orthographic), overview (the whole world at an angle),
// fixed (render.fixed_camera's pos and lookat). render/camera_rig.h places each one.
#include <string>

#include "sim/declared_keys.h"

namespace cosim {

enum class CameraKind { Chase, Orbit, Top, Overview, Fixed };

// The names scenarios, video files and the command line use, declared once.
inline constexpr ChoiceNames<CameraKind, 5> kCameraNames{{
    {CameraKind::Chase, "chase"},
    {CameraKind::Orbit, "orbit"},
    {CameraKind::Top, "top"},
    {CameraKind::Overview, "overview"},
    {CameraKind::Fixed, "fixed"},
}};

// Throws std::invalid_argument for an unknown name (the loader has already checked scenario
// names; this guards the command line).
CameraKind cameraKind(const std::string& name);
const char* cameraName(CameraKind kind);  // "chase", ...: as scenarios and video names say it
const char* cameraNames();                // "chase, orbit, top, overview or fixed", for messages

}  // namespace cosim
