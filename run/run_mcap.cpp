#include "run/run_mcap.h"

#include <algorithm>
#include <cmath>
#include <tuple>

#include "core/mcap_writer.h"
#include "render/run_moments.h"
#include "render/scene_shapes.h"
#include "run/foxglove_schemas.h"

namespace cosim {

namespace {

using nlohmann::json;

std::uint64_t nanoseconds(double t) {
  return static_cast<std::uint64_t>(std::llround(std::max(t, 0.0) * 1e9));
}
json xyz(const Eigen::Vector3d& v) {
  return {{"x", v.x()}, {"y", v.y()}, {"z", v.z()}};
}
json xyzw(const Eigen::Quaterniond& q) {
  return {{"x", q.x()}, {"y", q.y()}, {"z", q.z()}, {"w", q.w()}};
}
json rgba(double r, double g, double b, double a) {
  return {{"r", r}, {"g", g}, {"b", b}, {"a", a}};
}
json pose(const Eigen::Vector3d& p, const Eigen::Quaterniond& q) {
  return {{"position", xyz(p)}, {"orientation", xyzw(q)}};
}

json entity(const std::string& id, const std::string& frame, bool frame_locked) {
  return {{"timestamp", foxgloveTime(0)},
          {"frame_id", frame},
          {"id", id},
          {"lifetime", foxgloveTime(0)},
          {"frame_locked", frame_locked},
          {"cubes", json::array()},
          {"spheres", json::array()},
          {"cylinders", json::array()},
          {"lines", json::array()}};
}

// A shape as a primitive of `e`: capsules as the cylinder around them.
void addShape(json& e, const SceneShape& s) {
  const json colour = rgba(s.rgba[0], s.rgba[1], s.rgba[2], s.rgba[3]);
  Eigen::Vector3d size = s.size;
  const char* list = "cubes";
  if (s.kind == ShapeKind::Sphere || s.kind == ShapeKind::Ellipsoid) list = "spheres";
  if (s.kind == ShapeKind::Cylinder || s.kind == ShapeKind::Capsule) list = "cylinders";
  if (s.kind == ShapeKind::Capsule) size.z() += size.x();
  json p = {{"pose", pose(s.pos, s.rot)}, {"size", xyz(size)}, {"color", colour}};
  if (std::string(list) == "cylinders") {
    p["bottom_scale"] = 1.0;
    p["top_scale"] = 1.0;
  }
  e[list].push_back(p);
}

json worldUpdate(const WorldModel& world, const Scenario& scenario) {
  json e = entity("world", "world", false);
  const Eigen::Vector3d lo = scenario.world.bounds_min, hi = scenario.world.bounds_max;
  SceneShape floor;
  floor.pos = {0.5 * (lo.x() + hi.x()), 0.5 * (lo.y() + hi.y()), lo.z() - 0.01};
  floor.size = {hi.x() - lo.x(), hi.y() - lo.y(), 0.02};
  floor.rgba = {0.93f, 0.92f, 0.89f, 1.0f};
  addShape(e, floor);
  for (const SceneShape& s : staticWorldShapes(world)) addShape(e, s);
  return {{"deletions", json::array()}, {"entities", {e}}};
}

json vehiclesUpdate(const WorldModel& world, const RunLog& log) {
  json entities = json::array();
  for (std::size_t v = 0; v < log.vehicles.size() && v < world.vehicles().size(); ++v) {
    json e = entity(log.vehicles[v].name, log.vehicles[v].name, true);
    for (const SceneShape& s : vehicleShapes(world, v)) addShape(e, s);
    entities.push_back(e);
  }
  return {{"deletions", json::array()}, {"entities", entities}};
}

json strip(const std::vector<Eigen::Vector3d>& points, const json& colour, double thickness) {
  json pts = json::array();
  for (const auto& p : points) pts.push_back(xyz(p));
  return {{"type", 0},
          {"pose", pose(Eigen::Vector3d::Zero(), Eigen::Quaterniond::Identity())},
          {"thickness", thickness},
          {"scale_invariant", true},
          {"points", pts},
          {"color", colour},
          {"colors", json::array()},
          {"indices", json::array()}};
}

// Green (no error) through yellow to red (the run's largest error), as viewer.html colours it.
json errorColour(double e, double worst) {
  const double x = std::clamp(e / std::max(worst, 1e-9), 0.0, 1.0);
  return x < 0.5 ? rgba(0.1 + 1.7 * x, 0.6 + 0.5 * x, 0.31, 1.0)
                 : rgba(0.95, 0.85 - 1.5 * (x - 0.5), 0.31 - 0.5 * (x - 0.5), 1.0);
}

json pathsUpdate(const RunLog& log, const std::vector<std::vector<std::size_t>>& picks) {
  double worst = 0.0;
  for (const VehicleLog& v : log.vehicles)
    for (const LogSample& s : v.samples) worst = std::max(worst, (s.pos - s.ref_pos).norm());
  json entities = json::array();
  for (std::size_t v = 0; v < log.vehicles.size(); ++v) {
    const VehicleLog& vl = log.vehicles[v];
    json e = entity(vl.name + "/paths", "world", false);
    e["lines"].push_back(strip(vl.planned_path, rgba(0.18, 0.42, 0.85, 1.0), 3.0));
    std::vector<Eigen::Vector3d> ref, flown;
    json colours = json::array();
    for (std::size_t k : picks[v]) {
      ref.push_back(vl.samples[k].ref_pos);
      flown.push_back(vl.samples[k].pos);
      colours.push_back(errorColour((vl.samples[k].pos - vl.samples[k].ref_pos).norm(), worst));
    }
    e["lines"].push_back(strip(ref, rgba(0.33, 0.35, 0.4, 0.8), 1.5));
    json f = strip(flown, rgba(0.1, 0.6, 0.31, 1.0), 3.0);
    f["colors"] = colours;
    e["lines"].push_back(f);
    entities.push_back(e);
  }
  return {{"deletions", json::array()}, {"entities", entities}};
}

// The samples each vehicle exports: one per 1/rate seconds (every one for rate 0).
std::vector<std::vector<std::size_t>> exportedSamples(const RunLog& log, double rate) {
  std::vector<std::vector<std::size_t>> picks(log.vehicles.size());
  for (std::size_t v = 0; v < log.vehicles.size(); ++v) {
    double next = 0.0;
    const auto& s = log.vehicles[v].samples;
    for (std::size_t k = 0; k < s.size(); ++k)
      if (rate <= 0.0 || s[k].t + 1e-9 >= next || k + 1 == s.size()) {
        picks[v].push_back(k);
        if (rate > 0.0) next = std::floor(s[k].t * rate + 1e-9) / rate + 1.0 / rate;
      }
  }
  return picks;
}

json stateMessage(const LogSample& s, double max_thrust) {
  json thrusts = json::array();
  if (max_thrust > 0.0)
    for (int r = 0; r < 4; ++r) thrusts.push_back(s.rotor_thrust[r]);
  return {{"t", s.t},
          {"position", xyz(s.pos)},
          {"reference", xyz(s.ref_pos)},
          {"estimate", xyz(s.est_pos)},
          {"error_m", (s.pos - s.ref_pos).norm()},
          {"estimate_error_m", (s.est_pos - s.pos).norm()},
          {"speed_mps", s.vel.norm()},
          {"thrust_n", thrusts}};
}

}  // namespace

McapExport runToMcap(const Scenario& scenario, const RunRecord& record, double rate,
                     const std::string& library) {
  const WorldModel& world = *record.world;
  const RunLog& log = record.log;
  McapWriter w("", library);
  const auto schema = [&](const json& s) {
    return w.addSchema(s["title"].get<std::string>(), "jsonschema", s.dump());
  };
  const std::uint16_t scene = schema(sceneUpdateSchema()), tf = schema(frameTransformSchema());
  const std::uint16_t state = schema(vehicleStateSchema()), moment = schema(runMomentSchema());
  const auto dump = [](const json& j) {
    return j.dump(-1, ' ', false, json::error_handler_t::replace);
  };
  const std::uint16_t world_ch = w.addChannel(scene, "/world", "json");
  const std::uint16_t vehicles_ch = w.addChannel(scene, "/vehicles", "json");
  const std::uint16_t paths_ch = w.addChannel(scene, "/paths", "json");
  const std::uint16_t tf_ch = w.addChannel(tf, "/tf", "json");
  std::vector<std::uint16_t> state_ch;
  for (const VehicleLog& v : log.vehicles)
    state_ch.push_back(w.addChannel(state, "/vehicles/" + v.name + "/state", "json"));
  const std::uint16_t moments_ch = w.addChannel(moment, "/moments", "json");

  const auto picks = exportedSamples(log, rate);
  w.addMessage(world_ch, 0, dump(worldUpdate(world, scenario)));
  w.addMessage(vehicles_ch, 0, dump(vehiclesUpdate(world, log)));
  w.addMessage(paths_ch, 0, dump(pathsUpdate(log, picks)));

  // Every timed message, in time order (vehicle by vehicle within one instant).
  std::vector<std::tuple<std::uint64_t, std::uint16_t, std::string>> timed;
  for (std::size_t v = 0; v < log.vehicles.size(); ++v)
    for (std::size_t k : picks[v]) {
      const LogSample& s = log.vehicles[v].samples[k];
      const std::uint64_t ns = nanoseconds(s.t);
      timed.emplace_back(ns, tf_ch,
                         dump({{"timestamp", foxgloveTime(ns)},
                               {"parent_frame_id", "world"},
                               {"child_frame_id", log.vehicles[v].name},
                               {"translation", xyz(s.pos)},
                               {"rotation", xyzw(s.att.normalized())}}));
      timed.emplace_back(ns, state_ch[v], dump(stateMessage(s, log.vehicles[v].max_thrust)));
    }
  for (const RunMoment& m : runMoments(log, scenario.world, 1))
    timed.emplace_back(nanoseconds(m.t), moments_ch,
                       dump({{"kind", m.kind},
                             {"t", m.t},
                             {"vehicle", m.vehicle >= 0 ? log.vehicles[m.vehicle].name : ""},
                             {"value_m", m.value},
                             {"label", m.label}}));
  std::stable_sort(timed.begin(), timed.end(),
                   [](const auto& a, const auto& b) { return std::get<0>(a) < std::get<0>(b); });
  for (const auto& [ns, channel, data] : timed) w.addMessage(channel, ns, data);

  McapExport out;
  out.messages = w.messageCount();
  out.channels = static_cast<int>(5 + state_ch.size());
  out.bytes = w.finish();
  return out;
}

}  // namespace cosim
