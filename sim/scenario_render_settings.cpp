// Reading a scenario's `render:` section (part of sim/scenario_loader.cpp), whose keys
// sim/render_settings.h declares: the cameras of the run's videos (sim/camera_kind.h), the
// frames' size and rate, the time-lapse factor and how the pictures are drawn.
#include <string>

#include "sim/declared_key_reader.h"
#include "sim/scenario_sections.h"

namespace cosim {

namespace {

// render.fixed_camera, which the fixed camera needs.
void readFixedCamera(const YamlReader& r, const YAML::Node& n, Scenario& s) {
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
  if (!root["render"]) return;
  const YAML::Node n = root["render"];
  readDeclaredKeys(r, n, "render", s.render);
  readFixedCamera(r, n, s);
  // H.264 with yuv420p needs even frame sizes.
  if (s.render.width % 2 || s.render.height % 2)
    r.fail(n, "render", "width and height must be even (H.264, yuv420p)");
}

}  // namespace cosim
