#pragma once
// What a scenario's `render:` section asks for: the cameras of the run's videos (sim/
// camera_kind.h; fixed looks from fixed_pos at fixed_lookat), the frames' size and rate, the
// time-lapse factor and how the pictures are drawn (docs/rendering.md).
#include <Eigen/Core>
#include <vector>

#include "sim/camera_kind.h"

namespace cosim {

struct RenderSettings {
  CameraKind camera = CameraKind::Chase;  // the main video, video.mp4
  std::vector<CameraKind> cameras;        // more videos, one per camera: video_<camera>.mp4
  int width = 1280, height = 720, fps = 30;
  double speedup = 1.0;           // simulated seconds per second of video
  bool has_fixed_camera = false;  // render.fixed_camera: {pos: [x,y,z], lookat: [x,y,z]}
  Eigen::Vector3d fixed_pos = Eigen::Vector3d::Zero();
  Eigen::Vector3d fixed_lookat = Eigen::Vector3d::Zero();
  double obstacle_alpha = 1.0;  // below 1: obstacles are see-through
  bool png_frames = false;      // also write each video as frames_<camera>/NNNNN.png
  // A team's pictures draw every member's planned path and reference too (off: the flown paths
  // only; a grid plan's right angles, one per member, tangle a team's picture).
  bool team_plans = false;
  // A team's flown paths coloured by tracking error, as a single vehicle's (off: each member in
  // its own colour, so that each can be followed).
  bool team_error = false;
  // The drawn paths' and references' thickness as a fraction of the visible height at the
  // camera's focus: 0.0055 is about 4 px in a 720-line frame.
  double line_width = 0.0055;

  // The keys (sim/declared_keys.h); fixed_camera is read by sim/scenario_render_settings.cpp.
  // Width and height are even (H.264 with yuv420p), which is checked after them.
  template <class Visitor>
  void declareKeys(Visitor& v) {
    v.choice("camera", camera, kCameraNames, "the main video's camera (video.mp4)");
    v.choices("cameras", cameras, kCameraNames, "more videos, one per camera: video_<camera>.mp4");
    v.integer("width", width, 64, 3840, "px, even");
    v.integer("height", height, 64, 2160, "px, even");
    v.integer("fps", fps, 1, 240, "frames per second of video");
    v.number("speedup", speedup, 0.01, 1000.0, "the older name of `speed`");
    v.number("speed", speedup, 0.01, 1000.0,
             "simulated seconds per second of video (a time-lapse above 1); wins over `speedup`");
    v.custom("fixed_camera", "{pos, lookat}",
             "[x, y, z] each, different: the `fixed` camera's place and aim");
    v.number("obstacle_alpha", obstacle_alpha, 0.05, 1.0,
             "obstacles' opacity; below 1 see-through");
    v.boolean("png_frames", png_frames, "also write every frame as PNG (frames_<camera>/)");
    v.boolean("team_plans", team_plans,
              "a team's pictures also draw each member's planned path and reference");
    v.boolean("team_error", team_error,
              "a team's flown paths coloured by tracking error instead of one colour each");
    v.number("line_width", line_width, 0.0005, 0.05,
             "paths' and references' thickness, a fraction of the visible height at the focus "
             "(0.0055: about 4 px of 720; thicker for a paper's figure)");
  }
};

}  // namespace cosim
