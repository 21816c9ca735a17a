#include "sim/scenario_sensing.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <tuple>

#include "sim/sensors/sensor_presets.h"

namespace cosim {

namespace {

constexpr double kMaxLatency = 1.0;  // s; a GPS is about 0.1 s late, a second is a units mistake

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

// A noise figure: zero (a perfect sensor) or more; negative is a mistake.
double noiseValue(const YamlReader& r, const YAML::Node& n, const std::string& key) {
  const double v = r.number(n, key);
  if (v < 0.0) r.fail(n, key, "must be >= 0 (a standard deviation or density), got " + num(v));
  if (v > 1e6) r.fail(n, key, "must be at most 1e6, got " + num(v));
  return v;
}

double rateValue(const YamlReader& r, const YAML::Node& n, const std::string& key,
                 const Scenario& s) {
  const double physics_rate = 1.0 / s.sim.timestep;
  const double rate = r.number(n, key, 0.1, 1e6);
  if (rate > physics_rate * (1.0 + 1e-9))
    r.fail(n, key,
           "rate " + num(rate) + " Hz is above the physics rate (" + num(physics_rate) +
               " Hz, 1 / sim.timestep)");
  return rate;
}

double latencyValue(const YamlReader& r, const YAML::Node& n, const std::string& key,
                    const Scenario& s) {
  const double latency = noiseValue(r, n, key);
  if (latency >= s.sim.max_time)
    r.fail(n, key,
           "latency " + num(latency) + " s is longer than the run (sim.max_time " +
               num(s.sim.max_time) + " s)");
  if (latency > kMaxLatency) r.fail(n, key, "latency above 1 s");
  return latency;
}

void readImu(const YamlReader& r, const YAML::Node& n, const Scenario& s, ImuSettings& imu) {
  const std::string key = "sensors.imu";
  r.requireMap(n, key);
  r.checkKeys(n, key,
              {"rate", "gyro_noise", "accel_noise", "gyro_bias_walk", "accel_bias_walk",
               "gyro_bias_init", "accel_bias_init"});
  imu.present = true;
  if (n["rate"]) imu.rate = rateValue(r, n["rate"], key + ".rate", s);
  const std::pair<const char*, double*> fields[] = {{"gyro_noise", &imu.noise.gyro_noise},
                                                    {"accel_noise", &imu.noise.accel_noise},
                                                    {"gyro_bias_walk", &imu.noise.gyro_bias_walk},
                                                    {"accel_bias_walk", &imu.noise.accel_bias_walk},
                                                    {"gyro_bias_init", &imu.gyro_bias_init},
                                                    {"accel_bias_init", &imu.accel_bias_init}};
  for (const auto& [name, value] : fields)
    if (n[name]) *value = noiseValue(r, n[name], key + "." + name);
}

void readPosition(const YamlReader& r, const YAML::Node& n, const Scenario& s,
                  PositionSensorSettings& p) {
  const std::string key = "sensors.position";
  r.requireMap(n, key);
  r.checkKeys(n, key, {"rate", "noise", "latency"});
  p.present = true;
  if (n["rate"]) p.rate = rateValue(r, n["rate"], key + ".rate", s);
  if (n["noise"]) p.noise = noiseValue(r, n["noise"], key + ".noise");
  if (n["latency"]) p.latency = latencyValue(r, n["latency"], key + ".latency", s);
}

void readAttitude(const YamlReader& r, const YAML::Node& n, const Scenario& s,
                  AttitudeSensorSettings& a) {
  const std::string key = "sensors.attitude";
  r.requireMap(n, key);
  r.checkKeys(n, key, {"rate", "noise_deg", "latency"});
  a.present = true;
  if (n["rate"]) a.rate = rateValue(r, n["rate"], key + ".rate", s);
  if (n["noise_deg"]) a.noise_deg = noiseValue(r, n["noise_deg"], key + ".noise_deg");
  if (n["latency"]) a.latency = latencyValue(r, n["latency"], key + ".latency", s);
}

void readSensors(const YamlReader& r, const YAML::Node& n, Scenario& s) {
  r.requireMap(n, "sensors");
  r.checkKeys(n, "sensors", {"preset", "imu", "position", "attitude"});
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
    readImu(r, n["imu"], s, out.imu);
  }
  if (n["position"]) {
    if (!out.position.present) out.position = base.position;
    readPosition(r, n["position"], s, out.position);
  }
  if (n["attitude"]) {
    if (!out.attitude.present) out.attitude = base.attitude;
    readAttitude(r, n["attitude"], s, out.attitude);
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

// The estimators that filter sensor data (the rest is ground_truth).
bool isFilter(const std::string& name) {
  return name == "ekf" || name == "crazyflie_kalman";
}

// estimator.fuse: the EKF either way; the Crazyflie's estimator fuses on arrival only.
void readFuse(const YamlReader& r, const YAML::Node& n, const std::string& name, Scenario& s) {
  if (!isFilter(name))
    r.fail(n, "estimator.fuse", "only a filter fuses (name: ekf or crazyflie_kalman)");
  const std::string fuse = r.text(n, "estimator.fuse");
  if (fuse != "at_validity" && fuse != "on_arrival")
    r.fail(n, "estimator.fuse", "must be 'at_validity' or 'on_arrival'");
  if (name == "crazyflie_kalman" && fuse != "on_arrival")
    r.fail(n, "estimator.fuse",
           "crazyflie_kalman fuses each fix when it arrives, as the firmware does: only "
           "'on_arrival' (for latency compensation use name: ekf)");
  s.estimator.fix_timing = fuse == "on_arrival" ? FixTiming::OnArrival : FixTiming::AtValidity;
}

// crazyflie_kalman's drag term: estimator.drag (dragB_x/y/z, 1/s) and center_of_pressure (m).
void readKalmanDrag(const YamlReader& r, const YAML::Node& n, const std::string& name,
                    Scenario& s) {
  // dragB in 1/s (the Flapper's largest is 4.2), the centre of pressure within a metre.
  const struct {
    const char* key;
    Eigen::Vector3d* out;
    double least, most;
  } keys[] = {{"drag", &s.estimator.drag, 0.0, 100.0},
              {"center_of_pressure", &s.estimator.center_of_pressure, -1.0, 1.0}};
  for (const auto& k : keys) {
    if (!n[k.key]) continue;
    const std::string where = std::string("estimator.") + k.key;
    if (name != "crazyflie_kalman")
      r.fail(n[k.key], where, "only crazyflie_kalman has a drag term (name: crazyflie_kalman)");
    *k.out = r.vec3(n[k.key], where);
    if (!(k.out->minCoeff() >= k.least && k.out->maxCoeff() <= k.most))
      r.fail(n[k.key], where,
             "each component must be in [" + num(k.least) + ", " + num(k.most) + "]");
  }
}

void readEstimator(const YamlReader& r, const YAML::Node& root, Scenario& s) {
  const YAML::Node n = root["estimator"];
  const bool given = n.IsDefined() && !n.IsNull();
  std::string name = s.sensors.ideal() ? "ground_truth" : "ekf";
  if (given) {
    r.requireMap(n, "estimator");
    r.checkKeys(n, "estimator",
                {"name", "predict_rate", "fuse", "position_std", "attitude_std", "drag",
                 "center_of_pressure"});
    if (!n["name"])
      r.fail(n, "estimator", "missing 'name' (ekf, crazyflie_kalman or ground_truth)");
    name = r.text(n["name"], "estimator.name");
    if (!isFilter(name) && name != "ground_truth")
      r.fail(n["name"], "estimator.name", "must be 'ekf', 'crazyflie_kalman' or 'ground_truth'");
    if (n["predict_rate"]) {
      if (!isFilter(name))
        r.fail(n["predict_rate"], "estimator.predict_rate",
               "only a filter predicts (name: ekf or crazyflie_kalman)");
      // crazyflie_kalman predicts at whole ticks of its 1 kHz loop: at most every tick.
      const double most = name == "crazyflie_kalman" ? 1000.0 : 1e6;
      s.estimator.predict_rate = r.number(n["predict_rate"], "estimator.predict_rate", 0.1, most);
    }
    if (n["fuse"]) readFuse(r, n["fuse"], name, s);
    if (name == "crazyflie_kalman") s.estimator.fix_timing = FixTiming::OnArrival;
    // The fixes' assumed standard deviations: m (position), rad (attitude, at most pi).
    const auto fixStd = [&](const char* key, double most, double& out) {
      if (!n[key]) return;
      const std::string where = std::string("estimator.") + key;
      if (!isFilter(name))
        r.fail(n[key], where, "only a filter weighs fixes (name: ekf or crazyflie_kalman)");
      out = r.number(n[key], where, 1e-9, most);
    };
    fixStd("position_std", 1e3, s.estimator.position_std);
    fixStd("attitude_std", M_PI, s.estimator.attitude_std);
    readKalmanDrag(r, n, name, s);
  }
  s.estimator.name = name;
  if (!isFilter(name)) return;
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

void readModelError(const YamlReader& r, const YAML::Node& n, Scenario& s) {
  r.requireMap(n, "model_error");
  r.checkKeys(n, "model_error", {"mass", "inertia", "thrust_coefficient"});
  // Beliefs off by more than a factor of two are not a model error but a different vehicle.
  const std::pair<const char*, double*> fields[] = {
      {"mass", &s.model_error.mass},
      {"inertia", &s.model_error.inertia},
      {"thrust_coefficient", &s.model_error.thrust_coefficient}};
  for (const auto& [name, value] : fields)
    if (n[name]) *value = r.number(n[name], std::string("model_error.") + name, 0.5, 2.0);
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
  if (root["model_error"]) readModelError(r, root["model_error"], s);
}

}  // namespace cosim
