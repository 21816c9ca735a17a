// Reading a scenario's `render:` section (part of sim/scenario_loader.cpp): the cameras of the
// run's videos (sim/camera_kind.h), the frames' size and rate, the time-lapse factor and how the
// pictures are drawn.
#include <stdexcept>
#include <string>

#include "sim/scenario_sections.h"

namespace cosim {

namespace {

// render.camera, render.cameras and render.fixed_camera (which the fixed camera needs).
void readCameras(const YamlReader& r, const YAML::Node& n, Scenario& s) {
  const auto readCamera = [&](const YAML::Node& c, const std::string& key) {
    const std::string name = r.text(c, key);
    try {
      return cameraKind(name);
    } catch (const std::invalid_argument&) {
      r.fail(c, key, std::string("must be ") + cameraNames());
    }
  };
  if (n["camera"]) s.render.camera = readCamera(n["camera"], "render.camera");
  if (n["cameras"]) {
    if (!n["cameras"].IsSequence())
      r.fail(n["cameras"], "render.cameras", "must be a list of camera names");
    for (std::size_t i = 0; i < n["cameras"].size(); ++i)
      s.render.cameras.push_back(
          readCamera(n["cameras"][i], "render.cameras[" + std::to_string(i) + "]"));
  }
  if (n["fixed_camera"]) {
    const YAML::Node f = n["fixed_camera"];
    r.checkKeys(f, "render.fixed_camera", {"pos", "lookat"});
    if (!f["pos"] || !f["lookat"]) r.fail(f, "render.fixed_camera", "needs 'pos' and 'lookat'");
    s.render.fixed_pos = r.vec3(f["pos"], "render.fixed_camera.pos");
    s.render.fixed_lookat = r.vec3(f["lookat"], "render.fixed_camera.lookat");
    if ((s.render.fixed_pos - s.render.fixed_lookat).norm() < 1e-6)
      r.fail(f, "render.fixed_camera", "pos and lookat must differ");
    s.render.has_fixed_camera = true;
  }
  bool wants_fixed = s.render.camera == CameraKind::Fixed;
  for (const auto& c : s.render.cameras) wants_fixed = wants_fixed || c == CameraKind::Fixed;
  if (wants_fixed && !s.render.has_fixed_camera)
    r.fail(n, "render",
           "camera 'fixed' needs render.fixed_camera: {pos: [x, y, z], lookat: [x, y, z]}");
}

}  // namespace

void readRenderSection(const YamlReader& r, const YAML::Node& root, Scenario& s) {
  if (root["render"]) {
    const YAML::Node n = root["render"];
    r.checkKeys(n, "render",
                {"camera", "cameras", "width", "height", "fps", "speed", "speedup", "fixed_camera",
                 "obstacle_alpha", "png_frames", "team_plans"});
    readCameras(r, n, s);
    // render.speed: the time-lapse factor; speedup is its older name (speed wins, so
    // --video-speed and --set render.speed=X apply to files that still say speedup).
    for (const char* key : {"speedup", "speed"})
      if (n[key]) s.render.speedup = r.number(n[key], std::string("render.") + key, 0.01, 1000.0);
    if (n["obstacle_alpha"])
      s.render.obstacle_alpha = r.number(n["obstacle_alpha"], "render.obstacle_alpha", 0.05, 1.0);
    if (n["png_frames"]) s.render.png_frames = r.boolean(n["png_frames"], "render.png_frames");
    if (n["team_plans"]) s.render.team_plans = r.boolean(n["team_plans"], "render.team_plans");
    if (n["width"])
      s.render.width = static_cast<int>(r.integer(n["width"], "render.width", 64, 3840));
    if (n["height"])
      s.render.height = static_cast<int>(r.integer(n["height"], "render.height", 64, 2160));
    if (n["fps"]) s.render.fps = static_cast<int>(r.integer(n["fps"], "render.fps", 1, 240));
    // H.264 with yuv420p needs even frame sizes.
    if (s.render.width % 2 || s.render.height % 2)
      r.fail(n, "render", "width and height must be even (H.264, yuv420p)");
  }
}

}  // namespace cosim
