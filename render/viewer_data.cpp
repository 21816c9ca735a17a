#include "render/viewer_data.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>

#include "core/base64.h"
#include "render/overlay_palette.h"
#include "render/run_moments.h"
#include "render/scene_shapes.h"
#include "render/trail_decimation.h"

namespace cosim {

double viewerFrameRate(std::size_t vehicles, double duration) {
  const double samples = std::max<double>(1.0, vehicles) * std::max(duration, 1.0);
  return std::clamp(kViewerSampleBudget / samples, kViewerMinRate, kViewerMaxRate);
}

namespace {

double rounded(double v, double unit) {
  return std::round(v / unit) * unit;
}

// [kind, x, y, z, qx, qy, qz, qw, size x, size y, size z, r, g, b, a]
nlohmann::json shapesJson(const std::vector<SceneShape>& shapes) {
  nlohmann::json out = nlohmann::json::array();
  for (const SceneShape& s : shapes) {
    const Eigen::Quaterniond q = s.rot.normalized();
    out.push_back({shapeKindName(s.kind), rounded(s.pos.x(), 1e-4), rounded(s.pos.y(), 1e-4),
                   rounded(s.pos.z(), 1e-4), rounded(q.x(), 1e-5), rounded(q.y(), 1e-5),
                   rounded(q.z(), 1e-5), rounded(q.w(), 1e-5), rounded(s.size.x(), 1e-4),
                   rounded(s.size.y(), 1e-4), rounded(s.size.z(), 1e-4), rounded(s.rgba[0], 1e-3),
                   rounded(s.rgba[1], 1e-3), rounded(s.rgba[2], 1e-3), rounded(s.rgba[3], 1e-3)});
  }
  return out;
}

// Positions as unsigned 16-bit steps from a corner below everything shown: `step` metres each,
// a millimetre unless the scene spans more than 65 m.
struct Quantiser {
  Eigen::Vector3d origin;
  double step = 0.001;
  std::uint16_t operator()(double v, int axis) const {
    return static_cast<std::uint16_t>(
        std::clamp(std::lround((v - origin[axis]) / step), 0L, 65535L));
  }
};

Quantiser quantiserFor(const Scenario& scenario, const RunLog& log) {
  Eigen::Vector3d lo = scenario.world.bounds_min, hi = scenario.world.bounds_max;
  for (const VehicleLog& v : log.vehicles)
    for (const LogSample& s : v.samples)
      for (const Eigen::Vector3d& p : {s.pos, s.ref_pos, s.est_pos})
        if (p.allFinite()) {
          lo = lo.cwiseMin(p);
          hi = hi.cwiseMax(p);
        }
  lo -= Eigen::Vector3d::Constant(1.0);
  hi += Eigen::Vector3d::Constant(1.0);
  return {lo, std::max(0.001, (hi - lo).maxCoeff() / 65000.0)};
}

// The little-endian blob of 16-bit channels and its layout: where each channel starts.
class TrackPacker {
 public:
  void begin(const std::string& channel, int components, const char* type) {
    layout_[channel] = {{"offset", bytes_.size()}, {"components", components}, {"type", type}};
  }
  void put(int v) {
    const auto u = static_cast<std::uint16_t>(v);  // two's complement for the signed channels
    bytes_.push_back(static_cast<std::uint8_t>(u & 0xff));
    bytes_.push_back(static_cast<std::uint8_t>(u >> 8));
  }
  const std::vector<std::uint8_t>& bytes() const { return bytes_; }
  const nlohmann::json& layout() const { return layout_; }

 private:
  std::vector<std::uint8_t> bytes_;
  nlohmann::json layout_ = nlohmann::json::object();
};

// The sample at time t, interpolated linearly between the two logged around it (attitudes
// normalised after interpolation); the first or last sample outside the log.
class SampleClock {
 public:
  explicit SampleClock(const std::vector<LogSample>& s) : s_(s) {}
  LogSample at(double t) {
    while (i_ + 1 < s_.size() && s_[i_ + 1].t <= t) ++i_;
    if (i_ + 1 >= s_.size() || t <= s_[i_].t) return s_[i_];
    const LogSample &a = s_[i_], &b = s_[i_ + 1];
    const double w = (t - a.t) / std::max(b.t - a.t, 1e-12);
    LogSample r = a;
    r.pos = a.pos + w * (b.pos - a.pos);
    r.ref_pos = a.ref_pos + w * (b.ref_pos - a.ref_pos);
    r.est_pos = a.est_pos + w * (b.est_pos - a.est_pos);
    r.vel = a.vel + w * (b.vel - a.vel);
    r.rotor_thrust = a.rotor_thrust + w * (b.rotor_thrust - a.rotor_thrust);
    r.att = a.att.slerp(w, b.att).normalized();
    return r;
  }

 private:
  const std::vector<LogSample>& s_;
  std::size_t i_ = 0;
};

bool estimatesDiffer(const RunLog& log) {
  for (const VehicleLog& v : log.vehicles)
    for (const LogSample& s : v.samples)
      if ((s.est_pos - s.pos).squaredNorm() > 1e-12) return true;
  return false;
}

// Each vehicle's resampled frames, channel after channel.
void packVehicles(const RunLog& log, const Scenario& scenario, const Quantiser& q, int frames,
                  double rate, const std::vector<std::vector<double>>& errors, TrackPacker& pack) {
  const bool est = estimatesDiffer(log);
  bool thrust = false;
  for (const VehicleLog& v : log.vehicles) thrust = thrust || v.max_thrust > 0.0;
  std::vector<std::vector<LogSample>> at(log.vehicles.size());
  for (std::size_t v = 0; v < log.vehicles.size(); ++v) {
    std::vector<LogSample> fallback(1);
    if (v < scenario.vehicles.size())
      fallback[0].pos = fallback[0].ref_pos = scenario.vehicles[v].start;
    fallback[0].est_pos = fallback[0].pos;
    const auto& samples = log.vehicles[v].samples.empty() ? fallback : log.vehicles[v].samples;
    SampleClock clock(samples);
    for (int k = 0; k < frames; ++k) at[v].push_back(clock.at(k / rate));
  }
  const auto positions = [&](const char* name, Eigen::Vector3d LogSample::*field) {
    pack.begin(name, 3, "u16");
    for (const auto& frames_of : at)
      for (const LogSample& s : frames_of)
        for (int a = 0; a < 3; ++a) pack.put(q((s.*field)[a], a));
  };
  positions("pos", &LogSample::pos);
  positions("ref", &LogSample::ref_pos);
  if (est) positions("est", &LogSample::est_pos);
  // Each vehicle's tracking error at each frame (the last sample at or before it), in mm.
  pack.begin("err", 1, "u16");
  for (std::size_t v = 0; v < at.size(); ++v) {
    const std::vector<LogSample>& samples = log.vehicles[v].samples;
    std::size_t i = 0;
    for (int k = 0; k < frames; ++k) {
      while (i + 1 < samples.size() && samples[i + 1].t <= k / rate) ++i;
      const double e = v < errors.size() && i < errors[v].size() ? errors[v][i] : 0.0;
      pack.put(static_cast<int>(
          std::clamp(std::isfinite(e) ? std::lround(e * 1000.0) : 65535L, 0L, 65535L)));
    }
  }
  pack.begin("quat", 4, "i16");  // x, y, z, w
  for (const auto& frames_of : at)
    for (const LogSample& s : frames_of)
      for (double c : {s.att.x(), s.att.y(), s.att.z(), s.att.w()})
        pack.put(static_cast<int>(std::lround(std::clamp(c, -1.0, 1.0) * 32767.0)));
  pack.begin("vel", 3, "i16");  // cm/s
  for (const auto& frames_of : at)
    for (const LogSample& s : frames_of)
      for (int a = 0; a < 3; ++a)
        pack.put(static_cast<int>(std::clamp(std::lround(s.vel[a] * 100.0), -32767L, 32767L)));
  if (!thrust) return;
  pack.begin("thrust", 4, "u16");  // fraction of the vehicle's rotor limit, times 65535
  for (std::size_t v = 0; v < at.size(); ++v) {
    const double limit = log.vehicles[v].max_thrust > 0.0 ? log.vehicles[v].max_thrust : 1.0;
    for (const LogSample& s : at[v])
      for (int r = 0; r < 4; ++r)
        pack.put(static_cast<int>(
            std::lround(std::clamp(s.rotor_thrust[r] / limit, 0.0, 1.0) * 65535.0)));
  }
}

void packMovingObstacles(const RunLog& log, const Quantiser& q, int frames, double rate,
                         TrackPacker& pack) {
  if (log.moving_obstacles.empty()) return;
  pack.begin("moving", 2, "u16");
  for (const MovingObstacleLog& m : log.moving_obstacles) {
    std::size_t i = 0;
    for (int k = 0; k < frames; ++k) {
      const double t = k / rate;
      while (i + 1 < m.t.size() && m.t[i + 1] <= t) ++i;
      const Eigen::Vector3d p = m.pos.empty() ? Eigen::Vector3d::Zero() : m.pos[i];
      pack.put(q(p.x(), 0));
      pack.put(q(p.y(), 1));
    }
  }
}

nlohmann::json vehiclesJson(const WorldModel& world, const Scenario& scenario, const RunLog& log,
                            const RunRecord* record, const std::vector<double>& scale_tops,
                            nlohmann::json& models) {
  nlohmann::json out = nlohmann::json::array();
  for (std::size_t v = 0; v < log.vehicles.size(); ++v) {
    const VehicleLog& vl = log.vehicles[v];
    const bool known = v < scenario.vehicles.size() && v < world.vehicles().size();
    const std::string model = known ? scenario.vehicles[v].model : "unknown";
    if (known && !models.contains(model)) models[model] = shapesJson(vehicleShapes(world, v));
    // Corners only: a grid plan lists every cell it crosses and every wait (a 1000-robot
    // execution's plans were half of its 10 MB page).
    nlohmann::json path = nlohmann::json::array();
    for (const Eigen::Vector3d& p : polylineCorners(vl.planned_path))
      for (int a = 0; a < 3; ++a) path.push_back(rounded(p[a], 1e-3));
    out.push_back(
        {{"name", vl.name},
         {"model", model},
         {"ground", known && scenario.vehicles[v].kind == VehicleKind::GroundRobot},
         {"radius", rounded(vl.radius, 1e-4)},
         {"max_thrust", rounded(vl.max_thrust, 1e-4)},
         {"goal",
          {rounded(vl.goal.x(), 1e-3), rounded(vl.goal.y(), 1e-3), rounded(vl.goal.z(), 1e-3)}},
         {"reached_goal", vl.reached_goal},
         {"arrival_time", vl.reached_goal ? rounded(vl.arrival_time, 1e-3) : -1.0},
         {"controller", record && v < record->setup.vehicles.size()
                            ? record->setup.sectionsOf(v).controller.name
                            : std::string()},
         {"error_scale", scale_tops[v]},
         {"planned", path}});
  }
  return out;
}

// Each vehicle's tracking errors: the record's, else the distance to the logged reference.
std::vector<std::vector<double>> trackingErrors(const RunLog& log, const RunRecord* record) {
  if (record) return record->metrics.tracking_errors;
  std::vector<std::vector<double>> errors;
  for (const VehicleLog& v : log.vehicles) {
    std::vector<double>& e = errors.emplace_back();
    for (const LogSample& s : v.samples) e.push_back((s.pos - s.ref_pos).norm());
  }
  return errors;
}

}  // namespace

nlohmann::json viewerData(const WorldModel& world, const Scenario& scenario, const RunLog& log,
                          const std::string& title, const std::string& status,
                          const RunRecord* record) {
  const std::vector<std::vector<double>> errors = trackingErrors(log, record);
  std::vector<ErrorReference> references;
  for (std::size_t v = 0; v < log.vehicles.size(); ++v)
    references.push_back(record && v < record->setup.vehicles.size() ? record->errorReferenceOf(v)
                                                                     : ErrorReference::Trajectory);
  const std::vector<double> scale_tops =
      errorScaleTops(references, errors, scenario.sim.goal_tolerance);
  double duration = 0.0;
  std::size_t longest = 1;
  for (const VehicleLog& v : log.vehicles)
    if (!v.samples.empty()) {
      duration = std::max(duration, v.samples.back().t);
      longest = std::max(longest, v.samples.size());
    }
  const double rate = viewerFrameRate(log.vehicles.size(), duration);
  const int frames = static_cast<int>(std::floor(duration * rate + 1e-6)) + 1;
  const Quantiser q = quantiserFor(scenario, log);

  nlohmann::json d;
  d["title"] = title;
  d["status"] = status;
  // A team's plans and references are hidden until asked for, as in its pictures.
  d["team_plans"] = scenario.render.team_plans;
  // A team's flown paths in each member's colour unless it asks for the error colouring.
  d["team_error"] = scenario.render.team_error;
  d["style"] = visualLanguageJson(log.vehicles.size());
  d["duration"] = duration;
  d["rate"] = rate;
  d["frames"] = frames;
  d["bounds"] = {{"min",
                  {scenario.world.bounds_min.x(), scenario.world.bounds_min.y(),
                   scenario.world.bounds_min.z()}},
                 {"max",
                  {scenario.world.bounds_max.x(), scenario.world.bounds_max.y(),
                   scenario.world.bounds_max.z()}}};
  d["quant"] = {{"origin", {q.origin.x(), q.origin.y(), q.origin.z()}}, {"step", q.step}};
  d["obstacles"] = shapesJson(staticWorldShapes(world));
  nlohmann::json models = nlohmann::json::object();
  d["vehicles"] = vehiclesJson(world, scenario, log, record, scale_tops, models);
  d["models"] = models;
  nlohmann::json moving = nlohmann::json::array();
  for (const MovingObstacleLog& m : log.moving_obstacles)
    moving.push_back(
        {{"name", m.name}, {"shapes", shapesJson(movingObstacleShapes(world, m.name))}});
  d["moving"] = moving;

  // The searches look at about as many samples per vehicle as the replay has frames, or more.
  const int stride =
      std::max(1, static_cast<int>(longest / (4 * static_cast<std::size_t>(frames))));
  nlohmann::json moments = nlohmann::json::array();
  for (const RunMoment& m : runMoments(log, scenario.world, stride))
    moments.push_back({{"kind", m.kind},
                       {"t", rounded(m.t, 1e-3)},
                       {"vehicle", m.vehicle},
                       {"other", m.other},
                       {"value", rounded(m.value, 1e-4)},
                       {"label", m.label}});
  d["moments"] = moments;

  TrackPacker pack;
  packVehicles(log, scenario, q, frames, rate, errors, pack);
  packMovingObstacles(log, q, frames, rate, pack);
  d["layout"] = pack.layout();
  d["tracks"] = base64Encode(pack.bytes());
  return d;
}

}  // namespace cosim
