#pragma once
// Where the camera of a named view is at time t of a logged run. Every pose is a function of
// the log and t alone (no state carried between frames), so any frame can be rendered on its
// own and a re-render from the log reproduces the video exactly.
#include <Eigen/Core>
#include <cmath>
#include <string>

#include "sim/camera_kind.h"
#include "sim/run_log.h"
#include "sim/scenario.h"

namespace cosim {

// A MuJoCo free camera (mjvCamera's lookat/azimuth/elevation/distance, degrees) plus the
// vertical field of view it is rendered with.
struct CameraPose {
  Eigen::Vector3d lookat = Eigen::Vector3d::Zero();
  double azimuth = 0.0;    // the camera looks along this heading (degrees from +x)
  double elevation = 0.0;  // negative: looking down
  double distance = 1.0;
  double fovy_deg = 45.0;
  // Where the eye is: lookat - distance * forward.
  Eigen::Vector3d eye() const;
};

// Where `point` appears in a frame of `aspect` (width / height) filmed from `p`: (-1, -1) the
// bottom-left corner, (1, 1) the top-right; false if the point is behind the camera.
bool frameCoordinates(const CameraPose& p, const Eigen::Vector3d& point, double aspect,
                      Eigen::Vector2d& uv);

// Where the chase camera keeps its vehicle in the frame (frameCoordinates): clear of the legend
// in the bottom-left corner and the colour scale in the bottom-right (each up to about a third
// of the frame's height: frame_annotations.cpp), and of the frame's sides and top.
struct ChaseVehicleZone {
  static constexpr double kMaxAcross = 0.7;  // |u|
  static constexpr double kLowest = -0.4;    // v
  static constexpr double kHighest = 0.7;    // v
  static bool contains(const Eigen::Vector2d& uv) {
    return std::abs(uv.x()) <= kMaxAcross && uv.y() >= kLowest && uv.y() <= kHighest;
  }
};

class CameraRig {
 public:
  // aspect: frame width / height (the top view fits the world into it).
  CameraRig(const Scenario& scenario, const RunLog& log, double aspect);

  CameraPose pose(CameraKind kind, double t) const;

  // The overview: from beyond the world's (max x, max y) corner, 45 degrees down, placed so
  // the world's bounding box and every vehicle's start and goal fill the frame with `margin`
  // (a fraction of the frame's width and height) to spare on each side.
  static constexpr double kOverviewMargin = 0.06;

 private:
  // Seconds ahead the chase camera aims at (where the vehicle will be then).
  static constexpr double kChaseLookAheadSeconds = 2.0;
  // Where the chase camera looks at t (degrees): along the vehicle's motion, turned toward the
  // world's centre when that would show the sky beyond the world's edge.
  double chaseHeading(double t) const;
  // The chase camera's pose at t looking along `azimuth`, before obstacles are considered.
  CameraPose chaseAt(double t, double azimuth) const;
  Eigen::Vector3d chaseTarget(double t) const;  // the chased vehicle's position
  CameraPose chase(double t) const;
  // p with its aim moved toward `target` (the vehicle) just far enough that the vehicle is in
  // ChaseVehicleZone: a steep view from close by puts the point aimed ahead of the vehicle at
  // the centre and the vehicle itself low in the frame, under the legend.
  CameraPose keepInZone(CameraPose p, const Eigen::Vector3d& target) const;
  // The eye over the floor, clear of obstacles, with nothing between it and `target`.
  bool eyeIsClear(const CameraPose& p, const Eigen::Vector3d& target) const;
  // Whether the floor seen at the top edge of the frame (model lens) is within the world.
  bool topOfFrameInsideWorld(const CameraPose& p) const;
  // The largest eye distance up to p.distance from which the view is clear (eyeIsClear).
  double clearDistance(CameraPose p, const Eigen::Vector3d& target) const;
  // p made clear (eyeIsClear): looking down more steeply, else moving in.
  CameraPose clearPose(CameraPose p, const Eigen::Vector3d& target) const;
  // The share of the frame (a grid of rays) that meets an obstacle within `depth` of the eye.
  double nearOccludedShare(const CameraPose& p, double depth) const;
  static constexpr double kMostNearOccluded = 0.25;
  CameraPose overview() const;

  const Scenario& scenario_;
  const RunLog& log_;
  double aspect_;
  double duration_;
  CameraPose overview_;  // fixed for the whole run
};

}  // namespace cosim
