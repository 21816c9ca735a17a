#include "render/run_renderer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace cosim {

RunRenderer::RunRenderer(const WorldModel& world, const Scenario& scenario, const RunLog& log,
                         int width, int height)
    : world_(world), scenario_(scenario), log_(log) {
  const mjModel* m = world.model();
  ctx_ = std::make_unique<OffscreenContext>(m, width, height);
  data_ = mj_makeData(m);
  mjv_defaultScene(&scene_);
  // Room for the model's geoms plus path and trail segments.
  mjv_makeScene(m, &scene_, m->ngeom + 12000);
  mjv_defaultCamera(&camera_);
  mjv_defaultOption(&option_);
}

RunRenderer::~RunRenderer() {
  mjv_freeScene(&scene_);
  if (data_) mj_deleteData(data_);
}

double RunRenderer::endTime() const {
  double t = 0.0;
  for (const auto& v : log_.vehicles)
    if (!v.samples.empty()) t = std::max(t, v.samples.back().t);
  return t;
}

std::size_t RunRenderer::sampleIndex(const VehicleLog& v, double t) const {
  // Samples are in time order: binary search for the last sample at or before t.
  auto it = std::upper_bound(v.samples.begin(), v.samples.end(), t,
                             [](double time, const LogSample& s) { return time < s.t; });
  return it == v.samples.begin() ? 0 : static_cast<std::size_t>(it - v.samples.begin() - 1);
}

void RunRenderer::poseVehicles(double t) {
  const mjModel* m = world_.model();
  mj_resetData(m, data_);
  for (std::size_t v = 0; v < world_.vehicles().size() && v < log_.vehicles.size(); ++v) {
    const VehicleLog& vl = log_.vehicles[v];
    if (vl.samples.empty()) continue;
    const LogSample& s = vl.samples[sampleIndex(vl, t)];
    mjtNum* q = data_->qpos + world_.vehicles()[v].qpos_adr;
    q[0] = s.pos.x();
    q[1] = s.pos.y();
    q[2] = s.pos.z();
    q[3] = s.att.w();
    q[4] = s.att.x();
    q[5] = s.att.y();
    q[6] = s.att.z();
  }
  mj_kinematics(m, data_);
  mj_camlight(m, data_);
}

void RunRenderer::placeCamera(double t, const std::string& camera) {
  const Eigen::Vector3d lo = scenario_.world.bounds_min, hi = scenario_.world.bounds_max;
  const Eigen::Vector3d centre = 0.5 * (lo + hi);
  const double extent = (hi - lo).head<2>().norm();
  camera_.type = mjCAMERA_FREE;
  if (camera == "chase" && !log_.vehicles.empty() && !log_.vehicles[0].samples.empty()) {
    const VehicleLog& v = log_.vehicles[0];
    const std::size_t i = sampleIndex(v, t);
    // Heading from the displacement over the last 1.5 s: smooth, and defined from the log
    // alone, so any frame can be rendered on its own.
    const std::size_t j = sampleIndex(v, t - 1.5);
    Eigen::Vector3d d = v.samples[i].pos - v.samples[j].pos;
    if (d.head<2>().norm() < 0.2) d = v.goal - v.samples[i].pos;
    const double heading = std::atan2(d.y(), d.x()) * 180.0 / M_PI;
    for (int k = 0; k < 3; ++k) camera_.lookat[k] = v.samples[i].pos[k];
    camera_.azimuth = heading;  // MuJoCo's azimuth: the camera looks along this heading
    camera_.elevation = -22.0;
    camera_.distance = std::max(1.0, 16.0 * v.radius);
  } else if (camera == "top") {
    for (int k = 0; k < 3; ++k) camera_.lookat[k] = centre[k];
    camera_.lookat[2] = lo.z();
    camera_.azimuth = 90.0;
    camera_.elevation = -89.9;
    camera_.distance = 1.25 * extent;
  } else {  // overview
    for (int k = 0; k < 3; ++k) camera_.lookat[k] = centre[k];
    camera_.lookat[2] = lo.z();
    camera_.azimuth = 225.0;
    camera_.elevation = -42.0;
    camera_.distance = 1.05 * extent;
  }
  // Path lines keep about the same on-screen width at any camera distance.
  line_radius_ = 0.0022 * camera_.distance;
}

void RunRenderer::addSegment(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                             const Eigen::Vector3f& rgb, double radius) {
  if (scene_.ngeom >= scene_.maxgeom || (b - a).norm() < 1e-9) return;
  mjvGeom* g = scene_.geoms + scene_.ngeom;
  const float rgba[4] = {rgb.x(), rgb.y(), rgb.z(), 1.0f};
  mjv_initGeom(g, mjGEOM_CAPSULE, nullptr, nullptr, nullptr, rgba);
  mjv_makeConnector(g, mjGEOM_CAPSULE, radius, a.x(), a.y(), a.z(), b.x(), b.y(), b.z());
  g->emission = 0.6f;  // nearly flat colour: paths stay recognisable in shade
  g->category = mjCAT_DECOR;
  ++scene_.ngeom;
}

void RunRenderer::addSphere(const Eigen::Vector3d& p, double radius, const Eigen::Vector4f& rgba) {
  if (scene_.ngeom >= scene_.maxgeom) return;
  mjvGeom* g = scene_.geoms + scene_.ngeom;
  const mjtNum size[3] = {radius, radius, radius};
  const mjtNum pos[3] = {p.x(), p.y(), p.z()};
  const float c[4] = {rgba[0], rgba[1], rgba[2], rgba[3]};
  mjv_initGeom(g, mjGEOM_SPHERE, size, pos, nullptr, c);
  g->emission = 0.4f;
  g->category = mjCAT_DECOR;
  ++scene_.ngeom;
}

void RunRenderer::addOverlays(double t) {
  for (const VehicleLog& v : log_.vehicles) {
    for (std::size_t i = 1; i < v.planned_path.size(); ++i)
      addSegment(v.planned_path[i - 1], v.planned_path[i], kPlannedPathColour, line_radius_);
    if (!v.planned_path.empty()) addSphere(v.planned_path.front(), 3 * line_radius_, {0.1f, 0.8f, 0.2f, 0.9f});
    addSphere(v.goal, 3 * line_radius_, {0.9f, 0.1f, 0.1f, 0.9f});
    if (v.samples.empty()) continue;
    // The trail, decimated by distance: a new vertex every ~1.5 line widths of travel keeps it
    // smooth on screen while the geometry stays small (software rendering pays per triangle).
    const std::size_t last = sampleIndex(v, t);
    const double spacing = 1.5 * 2.0 * line_radius_;
    Eigen::Vector3d prev = v.samples.front().pos;
    for (std::size_t i = 1; i <= last; ++i) {
      const Eigen::Vector3d& p = v.samples[i].pos;
      if ((p - prev).norm() < spacing && i != last) continue;
      addSegment(prev, p, kFlownPathColour, 0.8 * line_radius_);
      prev = p;
    }
  }
}

void RunRenderer::render(double t, const std::string& camera, std::vector<std::uint8_t>& rgb,
                         bool overlay_text) {
  const mjModel* m = world_.model();
  poseVehicles(t);
  placeCamera(t, camera);
  mjv_updateScene(m, data_, &option_, nullptr, &camera_, mjCAT_ALL, &scene_);
  addOverlays(t);
  mjr_render(ctx_->viewport(), &scene_, ctx_->context());
  if (overlay_text && !log_.vehicles.empty() && !log_.vehicles[0].samples.empty()) {
    const VehicleLog& v = log_.vehicles[0];
    const LogSample& s = v.samples[sampleIndex(v, t)];
    char values[256];
    std::snprintf(values, sizeof values, "%.2f s\n%.2f m/s\n%.3f m", s.t, s.vel.norm(),
                  (s.pos - s.ref_pos).norm());
    const std::string planner = scenario_.planner_name.empty() ? "given waypoints" : scenario_.planner_name;
    const std::string labels = "time\nspeed\nerror to set-point\n";
    mjr_overlay(mjFONT_NORMAL, mjGRID_TOPLEFT, ctx_->viewport(), (labels + "planner").c_str(),
                (std::string(values) + "\n" + planner).c_str(), ctx_->context());
    mjr_overlay(mjFONT_NORMAL, mjGRID_BOTTOMLEFT, ctx_->viewport(), "planned path (orange)\nflown path (blue)",
                nullptr, ctx_->context());
  }
  ctx_->readRgb(rgb);
}

bool RunRenderer::project(const Eigen::Vector3d& p, Eigen::Vector2d& pixel) const {
  // The same projection mjr_render sets up from scene_.camera: an off-centre frustum at the
  // near plane, widened to the viewport's aspect ratio.
  const mjvGLCamera& c0 = scene_.camera[0];
  const mjvGLCamera& c1 = scene_.camera[1];
  // Average the two eyes (identical without stereo).
  const Eigen::Vector3d pos = 0.5 * (Eigen::Vector3d(c0.pos[0], c0.pos[1], c0.pos[2]) +
                                     Eigen::Vector3d(c1.pos[0], c1.pos[1], c1.pos[2]));
  const Eigen::Vector3d fwd(c0.forward[0], c0.forward[1], c0.forward[2]);
  const Eigen::Vector3d up(c0.up[0], c0.up[1], c0.up[2]);
  const Eigen::Vector3d right = fwd.cross(up);
  const Eigen::Vector3d d = p - pos;
  const double z = d.dot(fwd);
  if (z <= 0) return false;
  const double xn = d.dot(right) * c0.frustum_near / z;
  const double yn = d.dot(up) * c0.frustum_near / z;
  const double aspect = static_cast<double>(ctx_->width()) / ctx_->height();
  const double halfwidth = 0.5 * aspect * (c0.frustum_top - c0.frustum_bottom);
  const double u = (xn - (c0.frustum_center - halfwidth)) / (2 * halfwidth);
  const double v = (yn - c0.frustum_bottom) / (c0.frustum_top - c0.frustum_bottom);
  pixel = {u * ctx_->width(), (1.0 - v) * ctx_->height()};
  return true;
}

}  // namespace cosim
