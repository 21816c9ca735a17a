#include "render/camera_rig.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "render/camera_occlusion.h"
#include "render/log_lookup.h"

namespace cosim {

namespace {
constexpr double kDeg = M_PI / 180.0;
constexpr double kModelFovy = 45.0;  // <visual><global fovy> in sim/world_model.cpp
// The top view looks from far away through a narrow lens: nearly orthographic (parallel lines
// stay parallel, heights barely shift positions) with MuJoCo 2.2's perspective-only camera.
constexpr double kTopFovy = 8.0;
}  // namespace

Eigen::Vector3d CameraPose::eye() const {
  const double a = azimuth * kDeg, e = elevation * kDeg;
  const Eigen::Vector3d forward(std::cos(e) * std::cos(a), std::cos(e) * std::sin(a), std::sin(e));
  return lookat - distance * forward;
}

CameraRig::CameraRig(const Scenario& scenario, const RunLog& log, double aspect)
    : scenario_(scenario), log_(log), aspect_(aspect), duration_(logEndTime(log)) {
  overview_ = overview();
}

double CameraRig::chaseHeading(double t) const {
  const VehicleLog& v = log_.vehicles.front();
  const Eigen::Vector3d pos = v.samples[sampleIndexAt(v, t)].pos;
  // Heading from the displacement over the last 1.5 s (an average velocity: no jitter from
  // attitude wobble), blended with a constant lean toward the goal so the heading is defined
  // while hovering and never jumps.
  const Eigen::Vector3d moved = pos - v.samples[sampleIndexAt(v, t - 1.5)].pos;
  Eigen::Vector3d toward = v.goal - v.samples.front().pos;
  toward.z() = 0.0;
  if (toward.norm() > 1e-9) toward.normalize();
  const Eigen::Vector3d d = moved + 0.3 * toward;
  const double heading = d.head<2>().norm() > 1e-9 ? std::atan2(d.y(), d.x()) / kDeg : 0.0;
  // Near the world's edge, looking on would show the sky beyond it: turn toward the world's
  // centre, in 15 degree steps, until even the steepest view (chaseAt) keeps the floor at the
  // top of the frame.
  const Eigen::Vector3d centre = 0.5 * (scenario_.world.bounds_min + scenario_.world.bounds_max);
  const double to_centre = std::atan2(centre.y() - pos.y(), centre.x() - pos.x()) / kDeg;
  const double turn = std::remainder(to_centre - heading, 360.0);
  for (double step = 0.0; step < std::abs(turn); step += 15.0) {
    CameraPose p = chaseAt(t, heading + std::copysign(step, turn));
    if (topOfFrameInsideWorld(p)) return p.azimuth;
  }
  return heading + turn;
}

CameraPose CameraRig::chaseAt(double t, double azimuth) const {
  CameraPose p;
  const VehicleLog& v = log_.vehicles.front();
  const Eigen::Vector3d pos = v.samples[sampleIndexAt(v, t)].pos;
  p.azimuth = azimuth;
  p.distance = std::max(1.5, 20.0 * std::max(v.radius, 0.05));
  // Aim a little ahead, where the vehicle will be (the log knows): the path ahead and what
  // stands next to it are in view, the vehicle below the centre. Looking down over the
  // obstacles next to the vehicle; steeper near the world's edge, until the top of the frame
  // meets the floor inside the world rather than the sky beyond it. The look-ahead shrinks as
  // the camera tilts down (by cos(elevation)), so the vehicle stays as far below the centre.
  const Eigen::Vector3d ahead = v.samples[sampleIndexAt(v, t + kChaseLookAheadSeconds)].pos - pos;
  for (p.elevation = -38.0; p.elevation >= -64.0; p.elevation -= 2.0) {
    const double cap = 0.3 * p.distance * std::cos(p.elevation * kDeg) / std::cos(38.0 * kDeg);
    p.lookat = pos + (ahead.norm() > cap ? Eigen::Vector3d(ahead * (cap / ahead.norm())) : ahead);
    if (topOfFrameInsideWorld(p)) break;
  }
  p.elevation = std::max(p.elevation, -64.0);
  return p;
}

namespace {

// The camera's axes (MuJoCo's free camera: up is forward turned 90 degrees up).
void cameraAxes(const CameraPose& p, Eigen::Vector3d& forward, Eigen::Vector3d& up,
                Eigen::Vector3d& right) {
  const double a = p.azimuth * kDeg, e = p.elevation * kDeg;
  forward = {std::cos(e) * std::cos(a), std::cos(e) * std::sin(a), std::sin(e)};
  up = {-std::sin(e) * std::cos(a), -std::sin(e) * std::sin(a), std::cos(e)};
  right = forward.cross(up);
}

}  // namespace

bool frameCoordinates(const CameraPose& p, const Eigen::Vector3d& point, double aspect,
                      Eigen::Vector2d& uv) {
  Eigen::Vector3d forward, up, right;
  cameraAxes(p, forward, up, right);
  const Eigen::Vector3d d = point - p.eye();
  const double depth = d.dot(forward);
  if (depth <= 1e-9) return false;
  const double ty = std::tan(0.5 * p.fovy_deg * kDeg), tx = ty * aspect;
  uv = {d.dot(right) / (depth * tx), d.dot(up) / (depth * ty)};
  return true;
}

CameraPose CameraRig::keepInZone(CameraPose p, const Eigen::Vector3d& target) const {
  const auto inZone = [&](const CameraPose& q) {
    Eigen::Vector2d uv;
    return frameCoordinates(q, target, aspect_, uv) && ChaseVehicleZone::contains(uv);
  };
  if (inZone(p)) return p;
  // Bisect the share of the way from the aim to the vehicle (at the vehicle it is at the centre
  // of the frame): the least move that brings it into the zone, so the aim moves smoothly.
  const Eigen::Vector3d aim = p.lookat;
  double lo = 0.0, hi = 1.0;
  for (int i = 0; i < 14; ++i) {
    const double mid = 0.5 * (lo + hi);
    p.lookat = aim + mid * (target - aim);
    (inZone(p) ? hi : lo) = mid;
  }
  p.lookat = aim + hi * (target - aim);
  if (!eyeIsClear(p, target)) p.distance = clearDistance(p, target);
  return p;
}

bool CameraRig::topOfFrameInsideWorld(const CameraPose& p) const {
  // The rays through the frame's top corners and top centre (model lens) all meet the floor
  // within the world, a thirtieth of its size of slack: no sky beyond its edge shows.
  Eigen::Vector3d forward, up, right;
  cameraAxes(p, forward, up, right);
  const double ty = std::tan(0.5 * kModelFovy * kDeg), tx = ty * aspect_;
  const Eigen::Vector3d eye = p.eye();
  const Eigen::Vector3d lo = scenario_.world.bounds_min, hi = scenario_.world.bounds_max;
  const double margin = (hi - lo).head<2>().norm() / 30.0;
  for (double side : {-1.0, 0.0, 1.0}) {
    const Eigen::Vector3d ray = forward + ty * up + side * tx * right;
    if (ray.z() >= -1e-6) return false;  // at the horizon or above
    const Eigen::Vector3d hit = ray * ((eye.z() - lo.z()) / -ray.z()) + eye;
    if (hit.x() < lo.x() - margin || hit.x() > hi.x() + margin || hit.y() < lo.y() - margin ||
        hit.y() > hi.y() + margin)
      return false;
  }
  return true;
}

double CameraRig::nearOccludedShare(const CameraPose& p, double depth) const {
  // Rays through a 6 x 4 grid over the frame, each out to `depth`: the share that meets an
  // obstacle first. A wall beside the lens fills much of the frame without hiding the vehicle.
  Eigen::Vector3d forward, up, right;
  cameraAxes(p, forward, up, right);
  const double ty = std::tan(0.5 * kModelFovy * kDeg), tx = ty * aspect_;
  const Eigen::Vector3d eye = p.eye();
  int blocked = 0;
  constexpr int kColumns = 6, kRows = 4;
  for (int i = 0; i < kColumns; ++i)
    for (int j = 0; j < kRows; ++j) {
      const double u = (2.0 * i + 1.0) / kColumns - 1.0, v = (2.0 * j + 1.0) / kRows - 1.0;
      const Eigen::Vector3d ray = (forward + u * tx * right + v * ty * up).normalized();
      if (firstObstacleHit(scenario_.world.obstacles, eye, eye + depth * ray, 0.0) < 1.0) ++blocked;
    }
  return static_cast<double>(blocked) / (kColumns * kRows);
}

bool CameraRig::eyeIsClear(const CameraPose& p, const Eigen::Vector3d& target) const {
  // The eye stands over the floor, clear of every obstacle, and so does the first half of its
  // sight line: an obstacle right in front of the lens would fill the frame (farther ones turn
  // see-through when they hide the vehicle, run_renderer.cpp). Nothing stands between the
  // vehicle and the eye: the camera never films the back of a wall.
  const Eigen::Vector3d eye = p.eye();
  const Eigen::Vector3d lo = scenario_.world.bounds_min, hi = scenario_.world.bounds_max;
  if (!overFloor(eye, lo, hi)) return false;
  const std::vector<Obstacle>& obstacles = scenario_.world.obstacles;
  const double clearance = 0.05 * p.distance;
  if (firstObstacleHit(obstacles, eye, eye + 0.5 * (p.lookat - eye), clearance) < 1.0) return false;
  if (firstObstacleHit(obstacles, target, eye, 0.0) < 1.0) return false;
  // Obstacles nearer than half the way to the vehicle cover at most a quarter of the frame.
  return nearOccludedShare(p, 0.5 * (target - eye).norm()) <= kMostNearOccluded;
}

double CameraRig::clearDistance(CameraPose p, const Eigen::Vector3d& target) const {
  // Walk in from the wanted distance until the eye is clear; the closest allowed is a fifth.
  const double wanted = p.distance;
  constexpr int kSteps = 16;
  for (int k = 0; k <= kSteps; ++k) {
    p.distance = wanted * (1.0 - 0.8 * k / kSteps);
    if (eyeIsClear(p, target)) return p.distance;
  }
  return p.distance;
}

CameraPose CameraRig::clearPose(CameraPose p, const Eigen::Vector3d& target) const {
  // Looking down more steeply first (over a wall beside the path, its top is all that shows),
  // then moving in (in front of a wall behind the vehicle).
  const double elevation = p.elevation;
  for (double steeper : {0.0, 12.0, 24.0}) {
    p.elevation = std::max(-80.0, elevation - steeper);
    CameraPose q = p;
    q.distance = clearDistance(p, target);
    if (eyeIsClear(q, target)) return q;
  }
  p.elevation = elevation;
  p.distance = clearDistance(p, target);
  return p;
}

Eigen::Vector3d CameraRig::chaseTarget(double t) const {
  const VehicleLog& v = log_.vehicles.front();
  return v.samples[sampleIndexAt(v, t)].pos;
}

CameraPose CameraRig::chase(double t) const {
  // The heading is the circular mean of the headings over +-1 s, and the distance the closest
  // of the clear distances around t: the camera turns away from the world's edge and moves in
  // ahead of an obstacle and out again after it instead of jumping; still a function of t alone.
  constexpr double kWindow[] = {-1.0, -0.5, 0.0, 0.5, 1.0};
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  for (double dt : kWindow) {
    const double a = chaseHeading(t + dt) * kDeg;
    mean += Eigen::Vector2d(std::cos(a), std::sin(a));
  }
  const double azimuth = std::atan2(mean.y(), mean.x()) / kDeg;
  CameraPose p = chaseAt(t, azimuth);
  double distance = p.distance, elevation = p.elevation;
  for (double dt : kWindow) {
    const CameraPose q = clearPose(chaseAt(t + dt, azimuth), chaseTarget(t + dt));
    distance = std::min(distance, q.distance);
    elevation = std::min(elevation, q.elevation);
  }
  CameraPose smooth = p;
  smooth.distance = distance;
  smooth.elevation = elevation;
  if (eyeIsClear(smooth, chaseTarget(t))) return keepInZone(smooth, chaseTarget(t));
  return keepInZone(clearPose(p, chaseTarget(t)), chaseTarget(t));
}

CameraPose CameraRig::overview() const {
  CameraPose p;
  p.fovy_deg = kModelFovy;
  p.azimuth = 225.0;  // from beyond the (max x, max y) corner, looking back at the start side
  p.elevation = -45.0;
  const Eigen::Vector3d lo = scenario_.world.bounds_min, hi = scenario_.world.bounds_max;
  std::vector<Eigen::Vector3d> points;
  for (int c = 0; c < 8; ++c)
    points.emplace_back(c & 1 ? hi.x() : lo.x(), c & 2 ? hi.y() : lo.y(), c & 4 ? hi.z() : lo.z());
  for (const VehicleSpec& v : scenario_.vehicles) {
    points.push_back(v.start);
    points.insert(points.end(), v.waypoints.begin(), v.waypoints.end());
  }
  for (const VehicleLog& v : log_.vehicles) {
    points.push_back(v.goal);
    points.insert(points.end(), v.planned_path.begin(), v.planned_path.end());
    if (!v.samples.empty()) points.push_back(v.samples.front().pos);
  }
  // The camera's axes (MuJoCo's free camera: up is forward turned 90 degrees up).
  const double a = p.azimuth * kDeg, e = p.elevation * kDeg;
  const Eigen::Vector3d forward(std::cos(e) * std::cos(a), std::cos(e) * std::sin(a), std::sin(e));
  const Eigen::Vector3d up(-std::sin(e) * std::cos(a), -std::sin(e) * std::sin(a), std::cos(e));
  const Eigen::Vector3d right = forward.cross(up);
  // A point at depth z from the eye is inside the frame with the margin when its offsets from
  // the view axis satisfy |x| <= kx z and |y| <= ky z. In the camera's axes these are linear in
  // the eye position: x - kx z <= ex - kx ez and x + kx z >= ex + kx ez (the same for y). The
  // closest eye satisfying all of them centres the points' extreme bounds on each axis and
  // stands back as far as the tighter axis needs.
  const double ky = std::tan(0.5 * kModelFovy * kDeg) * (1.0 - 2.0 * kOverviewMargin);
  const double kx = ky * aspect_;
  double a_x = -HUGE_VAL, b_x = HUGE_VAL, a_y = -HUGE_VAL, b_y = HUGE_VAL;
  for (const Eigen::Vector3d& q : points) {
    const double x = q.dot(right), y = q.dot(up), z = q.dot(forward);
    a_x = std::max(a_x, x - kx * z);
    b_x = std::min(b_x, x + kx * z);
    a_y = std::max(a_y, y - ky * z);
    b_y = std::min(b_y, y + ky * z);
  }
  const double ez = std::min((b_x - a_x) / (2.0 * kx), (b_y - a_y) / (2.0 * ky));
  const Eigen::Vector3d eye = 0.5 * (a_x + b_x) * right + 0.5 * (a_y + b_y) * up + ez * forward;
  // Look at the depth of the world's centre (the lookat only sets where the camera turns).
  p.distance = std::max(1e-3, (0.5 * (lo + hi) - eye).dot(forward));
  p.lookat = eye + p.distance * forward;
  return p;
}

CameraPose CameraRig::pose(CameraKind kind, double t) const {
  const Eigen::Vector3d lo = scenario_.world.bounds_min, hi = scenario_.world.bounds_max;
  const Eigen::Vector3d centre = 0.5 * (lo + hi);
  const double extent = (hi - lo).head<2>().norm();
  CameraPose p;
  p.fovy_deg = kModelFovy;
  switch (kind) {
    case CameraKind::Chase:
      if (!log_.vehicles.empty() && !log_.vehicles.front().samples.empty()) return chase(t);
      [[fallthrough]];
    case CameraKind::Overview:
      return overview_;
    case CameraKind::Orbit: {
      // One revolution over the flight (at least 20 s per turn, so short flights do not spin).
      const double period = std::max(20.0, duration_);
      p.lookat = {centre.x(), centre.y(), lo.z() + 0.25 * (hi.z() - lo.z())};
      p.azimuth = 225.0 + 360.0 * t / period;
      p.elevation = -35.0;
      p.distance = 0.95 * extent;
      return p;
    }
    case CameraKind::Top: {
      p.fovy_deg = kTopFovy;
      p.lookat = {centre.x(), centre.y(), lo.z()};
      p.azimuth = 90.0;  // screen up = +y, screen right = +x
      p.elevation = -89.99;
      // Fit the bounds (with a 6 % margin) into the frame; the distance is from the floor.
      const double half_h = 1.06 * 0.5 * std::max(hi.y() - lo.y(), (hi.x() - lo.x()) / aspect_);
      p.distance = half_h / std::tan(0.5 * kTopFovy * kDeg);
      return p;
    }
    case CameraKind::Fixed: {
      const Eigen::Vector3d d = scenario_.render.fixed_lookat - scenario_.render.fixed_pos;
      p.lookat = scenario_.render.fixed_lookat;
      p.distance = d.norm();
      p.azimuth = std::atan2(d.y(), d.x()) / kDeg;
      p.elevation = std::asin(std::clamp(d.z() / p.distance, -1.0, 1.0)) / kDeg;
      return p;
    }
  }
  return p;
}

}  // namespace cosim
