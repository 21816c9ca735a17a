// The lines and markers a rendered frame draws over the scene: each vehicle's trail coloured by
// its tracking error (a team's in each member's own colour unless render.team_error), the planned
// paths, the dashed reference, heading arrows and goal spheres.
#include <algorithm>
#include <cmath>

#include "render/heading_arrow.h"
#include "render/overlay_budgets.h"
#include "render/run_renderer.h"
#include "render/trail_decimation.h"
#include "render/vehicle_marker.h"

namespace cosim {

void RunRenderer::addSegment(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                             const Eigen::Vector3f& rgb, double radius, float alpha, int type) {
  // Opaque lines (trails, plans, references) as ribbons in one draw call, unlit: their middle
  // shows the visual language's colour exactly, as the figures and viewer.html do.
  if (alpha >= 1.0f) return ribbons_.add(a, b, rgb, radius);
  if (scene_.ngeom >= scene_.maxgeom || (b - a).norm() < 1e-9) return;
  mjvGeom* g = scene_.geoms + scene_.ngeom;
  const float rgba[4] = {rgb.x(), rgb.y(), rgb.z(), alpha};
  mjv_initGeom(g, type, nullptr, nullptr, nullptr, rgba);
  mjv_makeConnector(g, type, radius, a.x(), a.y(), a.z(), b.x(), b.y(), b.z());
  g->emission = 0.7f;  // nearly flat colour: lines keep their colour in shade
  g->specular = 0.0f;
  g->category = mjCAT_DECOR;
  ++scene_.ngeom;
}

Eigen::Vector3d RunRenderer::towardEye(const Eigen::Vector3d& p, double widths) const {
  // Along the sight line the point stays on the same pixel; only its depth changes.
  const Eigen::Vector3d to_eye = eye_ - p;
  const double d = to_eye.norm(), shift = widths * line_radius_;
  return d > 2.0 * shift ? Eigen::Vector3d(p + to_eye * (shift / d)) : p;
}

void RunRenderer::addHeadingArrow(const LogSample& s, double radius, double width) {
  if (scene_.ngeom >= scene_.maxgeom) return;
  // Where the vehicle is going (its velocity), none while it is nearly still.
  const std::optional<Eigen::Vector3d> direction = headingArrowDirection(s.vel);
  if (!direction) return;
  const Eigen::Vector3d& forward = *direction;
  const Eigen::Vector3d from = s.pos + 0.6 * radius * forward;
  const Eigen::Vector3d to = s.pos + 2.2 * radius * forward;
  mjvGeom* g = scene_.geoms + scene_.ngeom;
  const float rgba[4] = {kHeadingColour.x(), kHeadingColour.y(), kHeadingColour.z(), 1.0f};
  mjv_initGeom(g, mjGEOM_ARROW, nullptr, nullptr, nullptr, rgba);
  mjv_makeConnector(g, mjGEOM_ARROW, width, from.x(), from.y(), from.z(), to.x(), to.y(), to.z());
  g->emission = 0.6f;
  g->category = mjCAT_DECOR;
  ++scene_.ngeom;
}

void RunRenderer::addSphere(const Eigen::Vector3d& p, double radius, const Eigen::Vector3f& rgb,
                            float alpha) {
  if (scene_.ngeom >= scene_.maxgeom) return;
  mjvGeom* g = scene_.geoms + scene_.ngeom;
  const mjtNum size[3] = {radius, radius, radius};
  const mjtNum pos[3] = {p.x(), p.y(), p.z()};
  const float c[4] = {rgb.x(), rgb.y(), rgb.z(), alpha};
  mjv_initGeom(g, mjGEOM_SPHERE, size, pos, nullptr, c);
  g->emission = 0.4f;
  g->category = mjCAT_DECOR;
  ++scene_.ngeom;
}

bool RunRenderer::isGround(std::size_t vehicle) const {
  return vehicle < scenario_.vehicles.size() &&
         scenario_.vehicles[vehicle].kind == VehicleKind::GroundRobot;
}

Eigen::Vector3f RunRenderer::plannedColour(std::size_t vehicle) const {
  return log_.vehicles.size() == 1 ? kPlannedPathColour : vehicleColour(vehicle);
}

void RunRenderer::addTrail(std::size_t vehicle, double t) {
  // Decimated for the line width rounded to a step of a quarter (on a log scale), and kept while
  // the width stays in that step: the chase camera's distance (and with it the width) changes a
  // little from frame to frame near obstacles. The step, not the history of widths, decides, so
  // a frame is the same whichever frames a renderer drew before it (parallel video workers).
  const double step = std::round(std::log(line_radius_) / std::log(1.25));
  const double width = std::pow(1.25, step);
  if (trail_line_radius_ != width) {
    // Vertices within a fraction of the line width of the logged positions look smooth; a
    // segment budget bounds the frame cost on long, winding flights.
    trail_vertices_.clear();
    for (std::size_t a = 0; a < log_.vehicles.size(); ++a) {
      TrailDecimation o;
      o.tolerance = 0.3 * width;
      o.max_segment = std::max(40.0 * width, 0.5);
      o.max_error_step = 0.06 * errorScale(a);
      std::vector<std::size_t> kept = decimateTrail(log_.vehicles[a].samples, errors_[a], o);
      while (kept.size() > static_cast<std::size_t>(trailBudget(log_.vehicles.size()))) {
        o.tolerance *= 2.0;
        o.max_segment *= 2.0;
        o.max_error_step *= 2.0;
        kept = decimateTrail(log_.vehicles[a].samples, errors_[a], o);
      }
      trail_vertices_.push_back(std::move(kept));
    }
    trail_line_radius_ = width;
  }
  const VehicleLog& v = log_.vehicles[vehicle];
  const std::vector<double>& err = errors_[vehicle];
  const std::vector<std::size_t>& kept = trail_vertices_[vehicle];
  const double scale = errorScale(vehicle);
  const bool by_error = trailsShowError();
  const Eigen::Vector3f own = vehicleColour(vehicle);
  const std::size_t last = sampleIndexAt(v, t);
  std::size_t from = 0;
  for (std::size_t k = 1; k < kept.size() && from < last; ++k) {
    const std::size_t i = std::min(kept[k], last);  // the trail ends at the vehicle
    addSegment(towardEye(v.samples[from].pos, 2.5), towardEye(v.samples[i].pos, 2.5),
               by_error ? errorColour(0.5 * (err[from] + err[i]) / scale) : own, line_radius_);
    from = i;
  }
}

void RunRenderer::addOverlays(double t, CameraKind camera) {
  const bool several = log_.vehicles.size() > 1;
  ribbons_.clear();
  // A team's picture shows where each member flew; the plans (a grid planner's right angles,
  // one per member) and the references only when the scenario asks (render.team_plans).
  const bool plans = !several || scenario_.render.team_plans;
  for (std::size_t a = 0; a < log_.vehicles.size(); ++a) {
    const VehicleLog& v = log_.vehicles[a];
    const Eigen::Vector3f planned = plannedColour(a);
    // The planned path as a wide band; the flown trail and the reference are drawn in front of
    // it (towardEye), so all three show where they coincide.
    if (plans) {
      const std::vector<Eigen::Vector3d>& plan = planned_paths_[a];
      for (std::size_t i = 1; i < plan.size(); ++i)
        addSegment(plan[i - 1], plan[i], planned, 2.0 * line_radius_);
    }
    // Start and goal; the goal stands on a thin pole to the floor so its height reads in
    // perspective views.
    const Eigen::Vector3d start = !v.planned_path.empty() ? v.planned_path.front()
                                  : !v.samples.empty()    ? v.samples.front().pos
                                                          : v.goal;
    if (!several) addSphere(start, 3.0 * line_radius_, kStartColour, 0.95f);
    // A team's goals see-through and its starts small and solid, each in the member's colour:
    // where one member's start is another's goal, both show.
    if (several) {
      addSphere(v.goal, 2.0 * line_radius_, planned, 0.5f);
      addSphere(start, 1.1 * line_radius_, planned, 1.0f);
    } else
      addSphere(v.goal, 3.5 * line_radius_, kGoalColour, 0.95f);
    if (plans) {
      const Eigen::Vector3d floor(v.goal.x(), v.goal.y(), scenario_.world.bounds_min.z());
      addSegment(floor, v.goal - Eigen::Vector3d(0, 0, 3.0 * line_radius_),
                 several ? planned : kGoalColour, 0.5 * line_radius_);
    }
    if (v.samples.empty()) continue;
    if (plans && references_[a] == ErrorReference::Trajectory) addReference(v);
    addTrail(a, t);
    // Where the vehicle is, for views where it is a few pixels small (and to tell agents apart),
    // and where it heads.
    const LogSample& s = v.samples[sampleIndexAt(v, t)];
    if (several) {
      const VehicleMarker m =
          vehicleMarker(v.radius, (s.pos - eye_).norm(), fovy_deg_, ctx_->height());
      addSphere(s.pos, m.radius, planned, m.solid ? 1.0f : 0.45f);
      addHeadingArrow(s, m.radius, 0.25 * m.radius);
      continue;
    }
    const double marker = std::max(1.6 * v.radius, 5.0 * line_radius_);
    if (camera != CameraKind::Chase) addSphere(s.pos, marker, Eigen::Vector3f(1, 1, 1), 0.35f);
    // Close up (chase) a slim arrow beside the airframe; from afar a bold one past the marker.
    if (camera == CameraKind::Chase)
      addHeadingArrow(s, 1.2 * v.radius, 0.08 * v.radius);
    else
      addHeadingArrow(s, marker, 0.25 * marker);
  }
}

void RunRenderer::addReference(const VehicleLog& v) {
  // The reference trajectory (only when it is a trajectory; a waypoint reference is the
  // planned path itself): dashes along the whole flight.
  double length = 0.0;
  for (std::size_t i = 1; i < v.samples.size(); ++i)
    length += (v.samples[i].ref_pos - v.samples[i - 1].ref_pos).norm();
  const double dash = std::max(4.0 * line_radius_, length / (2.0 * kReferenceDashBudget));
  std::size_t from = 0;
  bool draw = true;
  for (std::size_t i = 1; i < v.samples.size(); ++i) {
    if ((v.samples[i].ref_pos - v.samples[from].ref_pos).norm() < dash) continue;
    if (draw)
      addSegment(towardEye(v.samples[from].ref_pos, 5.0), towardEye(v.samples[i].ref_pos, 5.0),
                 kReferenceColour, 0.6 * line_radius_);
    draw = !draw;
    from = i;
  }
}

}  // namespace cosim
