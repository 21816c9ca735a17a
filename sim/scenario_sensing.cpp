#include "sim/scenario_sensing.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <tuple>

#include "sim/declared_key_reader.h"
#include "sim/sensors/sensor_presets.h"

namespace cosim {

namespace {

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

// A sensor block's declared keys (sim/sensors/sensor_settings.h), then what they must be in this
// run: a rate the physics can sample, a latency shorter than the run.
template <class Block>
void readBlock(const YamlReader& r, const YAML::Node& n, const std::string& key, const Scenario& s,
               Block& block) {
  readDeclaredKeys(r, n, key, block);
  block.present = true;
  const double physics_rate = 1.0 / s.sim.timestep;
  if (n["rate"] && block.rate > physics_rate * (1.0 + 1e-9))
    r.fail(n["rate"], key + ".rate",
           "rate " + num(block.rate) + " Hz is above the physics rate (" + num(physics_rate) +
               " Hz, 1 / sim.timestep)");
  if constexpr (requires { block.latency; })
    if (n["latency"] && block.latency >= s.sim.max_time)
      r.fail(n["latency"], key + ".latency",
             "latency " + num(block.latency) + " s is longer than the run (sim.max_time " +
                 num(s.sim.max_time) + " s)");
}

void readSensors(const YamlReader& r, const YAML::Node& n, Scenario& s) {
  r.checkKeys(n, "sensors", declaredKeyNames(s.sensors));
  SensorSettings& out = s.sensors;
  // A block without a preset starts from the motion-capture preset's values for that sensor.
  const SensorSettings base = sensorPreset("mocap");
  if (n["preset"]) {
    const std::string name = r.text(n["preset"], "sensors.preset");
    try {
      out = sensorPreset(name);
    } catch (const std::invalid_argument&) {
      r.fail(n["preset"], "sensors.preset",
             "unknown preset '" + name + "' (ideal, mocap, onboard)");
    }
  }
  if (n["imu"]) {
    if (!out.imu.present) out.imu = base.imu;
    readBlock(r, n["imu"], "sensors.imu", s, out.imu);
  }
  if (n["position"]) {
    if (!out.position.present) out.position = base.position;
    readBlock(r, n["position"], "sensors.position", s, out.position);
  }
  if (n["attitude"]) {
    if (!out.attitude.present) out.attitude = base.attitude;
    readBlock(r, n["attitude"], "sensors.attitude", s, out.attitude);
  }
  if (n["imu"] || n["position"] || n["attitude"]) out.preset = "custom";
  // The preset's own values must fit this run too (a preset's rate above a coarse physics rate).
  const double physics_rate = 1.0 / s.sim.timestep;
  for (const auto& [present, rate, name] :
       {std::tuple{out.imu.present, out.imu.rate, "imu"},
        std::tuple{out.position.present, out.position.rate, "position"},
        std::tuple{out.attitude.present, out.attitude.rate, "attitude"}})
    if (present && rate > physics_rate * (1.0 + 1e-9))
      r.fail(n, "sensors",
             std::string(name) + " rate " + num(rate) + " Hz is above the physics rate (" +
                 num(physics_rate) + " Hz); lower sim.timestep or the sensor's rate");
}

// Which estimator takes which key: a filter predicts, fuses and weighs fixes; only
// crazyflie_kalman has a drag term, predicts at most every tick of its 1 kHz loop and fuses on
// arrival, as the firmware does.
void checkEstimatorKeys(const YamlReader& r, const YAML::Node& n, EstimatorSettings& e) {
  const bool kalman = e.kind == EstimatorKind::CrazyflieKalman;
  const std::pair<const char*, const char*> filter_keys[] = {
      {"predict_rate", "only a filter predicts"},
      {"fuse", "only a filter fuses"},
      {"position_std", "only a filter weighs fixes"},
      {"attitude_std", "only a filter weighs fixes"}};
  for (const auto& [key, problem] : filter_keys)
    if (n[key] && !isFilter(e.kind))
      r.fail(n[key], std::string("estimator.") + key,
             std::string(problem) + " (name: ekf or crazyflie_kalman)");
  if (kalman && n["predict_rate"])  // the same message as the declared range's, narrower
    e.predict_rate = r.number(n["predict_rate"], "estimator.predict_rate", 0.1, 1000.0);
  if (kalman && n["fuse"] && e.fix_timing != FixTiming::OnArrival)
    r.fail(n["fuse"], "estimator.fuse",
           "crazyflie_kalman fuses each fix when it arrives, as the firmware does: only "
           "'on_arrival' (for latency compensation use name: ekf)");
  if (kalman) e.fix_timing = FixTiming::OnArrival;
  for (const char* key : {"drag", "center_of_pressure"})
    if (n[key] && !kalman)
      r.fail(n[key], std::string("estimator.") + key,
             "only crazyflie_kalman has a drag term (name: crazyflie_kalman)");
}

void readEstimator(const YamlReader& r, const YAML::Node& root, Scenario& s) {
  const YAML::Node n = root["estimator"];
  const bool given = n.IsDefined() && !n.IsNull();
  s.estimator.kind = s.sensors.ideal() ? EstimatorKind::GroundTruth : EstimatorKind::Ekf;
  if (given) {
    r.checkKeys(n, "estimator", declaredKeyNames(s.estimator));
    if (!n["name"])
      r.fail(n, "estimator", "missing 'name' (ekf, crazyflie_kalman or ground_truth)");
    readDeclaredKeys(r, n, "estimator", s.estimator);
    checkEstimatorKeys(r, n, s.estimator);
  }
  if (!isFilter(s.estimator.kind)) return;
  const std::string name = estimatorName(s.estimator.kind);
  // Named by the user: the estimator is at fault; chosen by default: the sensors are.
  const YAML::Node at = given ? n["name"] : root["sensors"];
  const std::string key = given ? "estimator.name" : "sensors";
  const std::string who =
      given ? "'" + name + "'" : "the default estimator 'ekf' (or estimator: {name: ground_truth})";
  if (s.sensors.ideal())
    r.fail(at, key,
           who +
               " needs sensors to fuse; sensing is ideal (add sensors: {preset: mocap} or "
               "onboard)");
  if (!s.sensors.imu.present)
    r.fail(at, key, who + " needs an IMU to propagate with (sensors.imu)");
  if (!s.sensors.position.present)
    r.fail(at, key, who + " needs a position sensor to correct with (sensors.position)");
}

}  // namespace
void readSensingSections(const YamlReader& r, const YAML::Node& root, Scenario& s) {
  const bool quadrotors =
      std::any_of(s.vehicles.begin(), s.vehicles.end(),
                  [](const VehicleSpec& v) { return v.kind == VehicleKind::Quadrotor; });
  for (const char* key : {"sensors", "estimator", "model_error"})
    if (root[key] && !quadrotors)
      r.fail(root[key], key,
             "sensing, estimation and model error are the quadrotors'; this scenario has none");
  if (root["sensors"]) readSensors(r, root["sensors"], s);
  readEstimator(r, root, s);
  if (root["model_error"]) readDeclaredKeys(r, root["model_error"], "model_error", s.model_error);
}

}  // namespace cosim
