#include "render/run_renderer.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "render/heading_arrow.h"
#include "render/overlay_budgets.h"
#include "render/state_box_lines.h"
#include "render/trail_decimation.h"
#include "render/vehicle_marker.h"
#include "sim/ground_vehicle_handles.h"

namespace cosim {

RunRenderer::RunRenderer(const Scenario& scenario, const RunRecord& record, int width, int height)
    : world_(*record.world),
      scenario_(scenario),
      record_(record),
      log_(record.log),
      rig_(scenario, log_, static_cast<double>(width) / height),
      errors_(record.metrics.tracking_errors),
      end_time_(logEndTime(log_)) {
  const RunLog& log = log_;
  const WorldModel& world = world_;
  const mjModel* m = world.model();
  ctx_ = std::make_unique<OffscreenContext>(m, width, height);
  data_ = mj_makeData(m);
  std::size_t planned_segments = 0;
  for (const VehicleLog& v : log.vehicles) {
    planned_paths_.push_back(polylineCorners(v.planned_path));
    planned_segments += planned_paths_.back().size();
  }
  mjv_defaultScene(&scene_);
  mjv_makeScene(m, &scene_,
                m->ngeom + 64 + static_cast<int>(planned_segments) +
                    static_cast<int>(log.vehicles.size()) *
                        (trailBudget(log.vehicles.size()) + kReferenceDashBudget + 16));
  mjv_defaultCamera(&camera_);
  mjv_defaultOption(&option_);
  // Each vehicle's error as its metrics measure it (the record's); one colour scale per kind of
  // reference, so a quadrotor's millimetres are not drawn on the robots' centimetre scale (or
  // vice versa).
  std::vector<double> max_error;
  for (std::size_t a = 0; a < log.vehicles.size(); ++a) {
    references_.push_back(record.errorReferenceOf(a));
    std::size_t k = 0;
    while (k < scales_.size() && scales_[k].reference != references_.back()) ++k;
    if (k == scales_.size()) {
      scales_.push_back({references_.back()});
      max_error.push_back(0.0);
    }
    scale_of_.push_back(k);
    for (double e : errors_[a]) max_error[k] = std::max(max_error[k], e);
  }
  for (std::size_t k = 0; k < scales_.size(); ++k)
    scales_[k].top = errorScaleMax(max_error[k], errorScaleFloor(scenario.sim.goal_tolerance));
  for (std::size_t i = 0; i < scenario.world.obstacles.size(); ++i)
    obstacle_geoms_.push_back(mj_name2id(m, mjOBJ_GEOM, ("obstacle" + std::to_string(i)).c_str()));
}

RunRenderer::~RunRenderer() {
  mjv_freeScene(&scene_);
  if (data_) mj_deleteData(data_);
}

void RunRenderer::poseVehicles(double t) {
  const mjModel* m = world_.model();
  mj_resetData(m, data_);
  for (std::size_t v = 0; v < world_.vehicles().size() && v < log_.vehicles.size(); ++v) {
    const VehicleLog& vl = log_.vehicles[v];
    if (vl.samples.empty()) continue;
    const LogSample& s = vl.samples[sampleIndexAt(vl, t)];
    if (world_.vehicles()[v].drive.planar_root) {  // a planar ground base: x, y, yaw joints
      const Eigen::Matrix3d R = s.att.toRotationMatrix();
      setPlanarPose(data_, world_.vehicles()[v], s.pos.head<2>(), std::atan2(R(1, 0), R(0, 0)));
      continue;
    }
    mjtNum* q = data_->qpos + world_.vehicles()[v].qpos_adr;
    q[0] = s.pos.x();
    q[1] = s.pos.y();
    q[2] = s.pos.z();
    q[3] = s.att.w();
    q[4] = s.att.x();
    q[5] = s.att.y();
    q[6] = s.att.z();
  }
  // Moving obstacles (mocap bodies) where the log saw them.
  for (const MovingObstacleLog& o : log_.moving_obstacles) {
    const int body = mj_name2id(m, mjOBJ_BODY, o.name.c_str());
    if (body < 0 || m->body_mocapid[body] < 0 || o.t.empty()) continue;
    const auto it = std::upper_bound(o.t.begin(), o.t.end(), t);
    const std::size_t k = it == o.t.begin() ? 0 : static_cast<std::size_t>(it - o.t.begin()) - 1;
    for (int i = 0; i < 2; ++i) data_->mocap_pos[3 * m->body_mocapid[body] + i] = o.pos[k][i];
  }
  mj_kinematics(m, data_);
  mj_camlight(m, data_);
}

void RunRenderer::applyCamera(const CameraPose& pose) {
  camera_.type = mjCAMERA_FREE;
  for (int k = 0; k < 3; ++k) camera_.lookat[k] = pose.lookat[k];
  camera_.azimuth = pose.azimuth;
  camera_.elevation = pose.elevation;
  camera_.distance = pose.distance;
  eye_ = pose.eye();
  fovy_deg_ = pose.fovy_deg;
  const double visible_height = 2.0 * pose.distance * std::tan(0.5 * pose.fovy_deg * M_PI / 180.0);
  // Lines are render.line_width of the visible height thick at the camera's focus.
  line_radius_ = 0.5 * scenario_.render.line_width * visible_height;
}

void RunRenderer::fadeObstacles(const CameraPose& pose, CameraKind camera, double t) {
  const mjModel* m = world_.model();
  // Obstacles between the chase camera and its vehicle would hide it: they turn see-through.
  std::vector<int> occluders;
  if (camera == CameraKind::Chase && !log_.vehicles.empty() && !log_.vehicles[0].samples.empty()) {
    const VehicleLog& v = log_.vehicles[0];
    const Eigen::Vector3d eye = pose.eye(), target = v.samples[sampleIndexAt(v, t)].pos;
    for (std::size_t i = 0; i < scenario_.world.obstacles.size(); ++i) {
      const Obstacle& o = scenario_.world.obstacles[i];
      // Sample the sight line up to the vehicle's bounding sphere (signedDistance is exact).
      const int samples = 48;
      for (int k = 0; k < samples; ++k) {
        const Eigen::Vector3d p = eye + (target - eye) * (k / static_cast<double>(samples));
        if ((p - target).norm() < v.radius) break;
        if (o.signedDistance(p) < 0.5 * v.radius) {
          occluders.push_back(obstacle_geoms_[i]);
          break;
        }
      }
    }
  }
  const float alpha = static_cast<float>(scenario_.render.obstacle_alpha);
  if (alpha >= 1.0f && occluders.empty()) return;
  for (int i = 0; i < scene_.ngeom; ++i) {
    mjvGeom& g = scene_.geoms[i];
    // Static world geometry (body 0) except the floor: the scenario's obstacles and includes.
    if (g.objtype != mjOBJ_GEOM || g.objid < 0 || g.objid == world_.floorGeom() ||
        m->geom_bodyid[g.objid] != 0)
      continue;
    const bool occluding =
        std::find(occluders.begin(), occluders.end(), g.objid) != occluders.end();
    g.rgba[3] = std::min(alpha, occluding ? 0.3f : 1.0f);
  }
}

void RunRenderer::hideTinyVehicles(double t) {
  // A team member under a few pixels is drawn as its marker alone (addOverlays): its airframe's
  // geoms would cost as much to rasterise as a larger one's and show as a speck.
  if (log_.vehicles.size() < 2) return;
  const mjModel* m = world_.model();
  std::vector<int> hidden;  // root bodies
  for (std::size_t v = 0; v < world_.vehicles().size() && v < log_.vehicles.size(); ++v) {
    const VehicleLog& vl = log_.vehicles[v];
    if (vl.samples.empty() || world_.vehicles()[v].body < 0) continue;
    const Eigen::Vector3d p = vl.samples[sampleIndexAt(vl, t)].pos;
    if (vehicleMarker(vl.radius, (p - eye_).norm(), fovy_deg_, ctx_->height()).solid)
      hidden.push_back(m->body_rootid[world_.vehicles()[v].body]);
  }
  if (hidden.empty()) return;
  int kept = 0;
  for (int i = 0; i < scene_.ngeom; ++i) {
    const mjvGeom& g = scene_.geoms[i];
    const bool tiny = g.objtype == mjOBJ_GEOM && g.objid >= 0 &&
                      std::find(hidden.begin(), hidden.end(),
                                m->body_rootid[m->geom_bodyid[g.objid]]) != hidden.end();
    if (!tiny) scene_.geoms[kept++] = g;
  }
  scene_.ngeom = kept;
}

void RunRenderer::annotate(double t) {
  FrameAnnotations ann(ctx_->context(), ctx_->viewport());
  std::vector<StateBoxVehicle> states;
  bool ground = false, flying = false;
  for (std::size_t a = 0; a < log_.vehicles.size(); ++a) {
    const VehicleLog& v = log_.vehicles[a];
    ground = ground || isGround(a);
    flying = flying || !isGround(a);
    if (v.samples.empty()) continue;
    const std::size_t i = sampleIndexAt(v, t);
    StateBoxVehicle& s = states.emplace_back();
    s.name = v.name;
    s.kind = isGround(a) ? VehicleKind::GroundRobot : VehicleKind::Quadrotor;
    s.speed = v.samples[i].vel.norm();
    s.error = errors_[a][i];
    s.reference = references_[a];
    // As the simulation decides arrival (ground robots on the floor plane), from the log alone
    // so a re-render says the same.
    Eigen::Vector3d off = v.samples[i].pos - v.goal;
    if (s.kind == VehicleKind::GroundRobot) off.z() = 0.0;
    s.at_goal = off.norm() < scenario_.sim.goal_tolerance;
  }
  const auto plannerName = [this](const std::string& name) {
    return pathSourceName(scenario_, name);
  };
  std::vector<StateLine> planners;
  if (ground && flying) {
    planners.emplace_back("robot planner", plannerName(scenario_.motion.planner.name));
    planners.emplace_back("quadrotor planner", plannerName(scenario_.aerial.planner.name));
  } else {
    planners.emplace_back("planner", plannerName(scenario_.motion.planner.name));
  }
  // Each group's controller, as the run resolved it (a team's quadrotors over robots fly their
  // own).
  const RunSetup& setup = record_.setup;
  if (ground && flying &&
      setup.robot_sections.controller.name != setup.quadrotor_sections.controller.name) {
    planners.emplace_back("robot controller", setup.robot_sections.controller.name);
    planners.emplace_back("quadrotor controller", setup.quadrotor_sections.controller.name);
  } else {
    planners.emplace_back("controller", setup.primarySections().controller.name);
  }
  // MuJoCo 2.2's smallest font is 18 px high (its 50 % scale falls back to 100 %): a frame
  // with room for fewer than 30 lines (640x360) gets short labels and fewer of them, so the
  // boxes cover about the same share of it as of a 1280x720 frame.
  const bool compact = ann.linesFitting(1.0) < 30;
  // The state box may take up to 45 % of the frame's height (the legend is below it).
  const int room = compact ? 3 : std::max(5, ann.linesFitting(0.45));
  overlay_boxes_.clear();
  overlay_boxes_.push_back(
      ann.stateBox(stateBoxLines(t, states, planners, static_cast<std::size_t>(room))));
  const int legend_room = compact ? 3 : std::max(3, ann.linesFitting(0.4));
  overlay_boxes_.push_back(
      ann.legend(legendEntries(static_cast<std::size_t>(legend_room), compact)));
  // A team's trails in their vehicles' colours have no error scale to read.
  for (std::size_t k = 0; trailsShowError() && k < scales_.size(); ++k) {
    // One scale: its full name; one per kind of vehicle: the kind, and short names.
    const ErrorReference r = scales_[k].reference;
    const std::string kind = r == ErrorReference::TimedPlan ? "robots" : "quadrotors";
    const std::string title =
        compact ? (scales_.size() == 1 ? std::string("error [m]") : kind + " error [m]")
        : scales_.size() == 1 ? std::string("error to ") + errorReferenceName(r) + " [m]"
                              : kind + ": error to " + errorReferenceShortName(r) + " [m]";
    overlay_boxes_.push_back(ann.errorScale(scales_[k].top, title, static_cast<int>(k), compact));
  }
}

void RunRenderer::render(double t, CameraKind camera, std::vector<std::uint8_t>& rgb,
                         bool annotate_frame) {
  const mjModel* m = world_.model();
  using Clock = std::chrono::steady_clock;
  const auto since = [](Clock::time_point& t0) {
    const Clock::time_point now = Clock::now();
    const double s = std::chrono::duration<double>(now - t0).count();
    t0 = now;
    return s;
  };
  Clock::time_point t0 = Clock::now();
  poseVehicles(t);
  const CameraPose pose = rig_.pose(camera, t);
  applyCamera(pose);
  mjv_updateScene(m, data_, &option_, nullptr, &camera_, mjCAT_ALL, &scene_);
  if (std::abs(pose.fovy_deg - m->vis.global.fovy) > 1e-9) {
    // A narrower lens than the model's: shrink the frustum at the near plane (the eye and its
    // direction are already set from the pose).
    const double k = std::tan(0.5 * pose.fovy_deg * M_PI / 180.0) /
                     std::tan(0.5 * m->vis.global.fovy * M_PI / 180.0);
    for (auto& c : scene_.camera) {
      // The eye is far away: move the near plane out too (same view, finer depth resolution).
      const float q = std::max(1.0f, static_cast<float>(0.3 * pose.distance) / c.frustum_near);
      c.frustum_near *= q;
      c.frustum_bottom *= static_cast<float>(k) * q;
      c.frustum_top *= static_cast<float>(k) * q;
      c.frustum_center *= static_cast<float>(k) * q;
      c.frustum_far = std::max(c.frustum_far, static_cast<float>(2.0 * pose.distance));
    }
  }
  if (camera == CameraKind::Top) {
    // Straight down, the headlight meets the floor head-on and washes everything out: dim it
    // so the sun's shading and shadows show the obstacles' shapes.
    for (int i = 0; i < scene_.nlight; ++i)
      if (scene_.lights[i].headlight)
        for (int k = 0; k < 3; ++k) {
          scene_.lights[i].diffuse[k] *= 0.3f;
          scene_.lights[i].ambient[k] *= 0.75f;
        }
  }
  // Shadows only where they show the obstacles' shapes (the fixed views from above). In the
  // moving chase view the 1024-texel shadow map draws thin lines' shadows as jagged dots, and
  // the shadow pass costs a second pass over every triangle.
  scene_.flags[mjRND_SHADOW] = camera == CameraKind::Top || camera == CameraKind::Overview;
  fadeObstacles(pose, camera, t);
  hideTinyVehicles(t);
  timings_.model_geoms = scene_.ngeom;
  timings_.scene = since(t0);
  addOverlays(t, camera);
  timings_.overlay_geoms = scene_.ngeom - timings_.model_geoms;
  timings_.ribbon_segments = static_cast<int>(ribbons_.size());
  timings_.overlays = since(t0);
  mjr_render(ctx_->viewport(), &scene_, ctx_->context());
  const int floor = world_.floorGeom();
  ribbons_.draw(eye_, RibbonBatch::shadowOf(scene_, floor >= 0 ? data_->geom_xpos[3 * floor + 2]
                                                               : scenario_.world.bounds_min.z()));
  mjr_finish();  // OSMesa rasterises when asked for the pixels: count that as rendering
  timings_.render = since(t0);
  if (annotate_frame && !log_.vehicles.empty()) annotate(t);
  timings_.annotate = since(t0);
  ctx_->readRgb(rgb);
  timings_.read = since(t0);
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
