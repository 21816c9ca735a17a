#include "sim/airframe_file.h"

#include "control/quadrotor_params.h"
#include "core/input_error.h"
#include "core/input_file.h"
#include "sim/yaml_document.h"
#include "sim/yaml_reader.h"

namespace cosim {

namespace {

// A key's number: the scalar itself or its mapping's `value`.
YAML::Node valueNode(const YamlReader& r, const YAML::Node& n, const std::string& key) {
  if (!n.IsMap()) return n;
  r.checkKeys(n, key, {"value", "ci95", "residual", "residual_unit", "unit", "samples"});
  if (!n["value"]) r.fail(n, key, "needs a 'value'");
  return n["value"];
}

}  // namespace

AirframeFile readAirframeFile(const std::filesystem::path& path) {
  const std::string file = path.string();
  const YAML::Node root =
      loadYamlDocument(readInputFile(file, kMaxScenarioFileBytes, "airframe file"), file);
  const YamlReader r(file);
  AirframeFile a;
  a.file = path;
  if (!root.IsDefined() || root.IsNull()) return a;
  r.requireMap(root, "");
  r.checkKeys(
      root, "",
      {"mass", "thrust_coefficient", "time_constant_up", "time_constant_down", "motor_delay",
       "rotor_drag_coefficient", "gyro_noise", "accel_noise", "motor_speed_coefficients"});
  // The ranges of the model file's own constants (sim/quadrotor_vehicle_handles.cpp).
  const struct {
    const char* key;
    std::optional<double>* field;
    double lo, hi;
  } numbers[] = {{"mass", &a.mass, 1e-4, 1e4},
                 {"thrust_coefficient", &a.thrust_coefficient, 1e-12, 1.0},
                 {"time_constant_up", &a.time_constant_up, 1e-4, 10.0},
                 {"time_constant_down", &a.time_constant_down, 1e-4, 10.0},
                 {"motor_delay", &a.motor_delay, 0.0, 1.0},
                 {"rotor_drag_coefficient", &a.rotor_drag_coefficient, 0.0, 1.0},
                 {"gyro_noise", &a.gyro_noise, 0.0, 1.0},
                 {"accel_noise", &a.accel_noise, 0.0, 10.0}};
  for (const auto& f : numbers)
    if (root[f.key]) *f.field = r.number(valueNode(r, root[f.key], f.key), f.key, f.lo, f.hi);
  if (const YAML::Node c = root["motor_speed_coefficients"]) {
    const std::string key = "motor_speed_coefficients";
    const YAML::Node v = valueNode(r, c, key);
    if (!v.IsSequence() || v.size() != 3)
      r.fail(v, key, "needs three numbers [c0, c1, c2] (rad/s, rad/s/V, rad/s/V^2)");
    std::array<double, 3> coefficients{};
    for (std::size_t i = 0; i < 3; ++i)
      coefficients[i] = r.number(v[i], key + "[" + std::to_string(i) + "]", -1e7, 1e7);
    a.motor_speed_coefficients = coefficients;
  }
  return a;
}

void applyAirframeFile(const AirframeFile& a, QuadrotorParams& p) {
  if (a.thrust_coefficient) p.thrust_coefficient = *a.thrust_coefficient;
  if (a.time_constant_up) p.time_constant_up = *a.time_constant_up;
  if (a.time_constant_down) p.time_constant_down = *a.time_constant_down;
  if (a.motor_delay) p.motor_delay = *a.motor_delay;
  if (a.rotor_drag_coefficient) p.rotor_drag_coefficient = *a.rotor_drag_coefficient;
  // The motor map drives the motor on a battery (vehicles[i].battery); vehicles[i].motor_speed_map,
  // applied after this, wins over it.
  if (a.motor_speed_coefficients)
    p.motor_speed_map =
        Eigen::Vector3d((*a.motor_speed_coefficients)[0], (*a.motor_speed_coefficients)[1],
                        (*a.motor_speed_coefficients)[2]);
}

}  // namespace cosim
