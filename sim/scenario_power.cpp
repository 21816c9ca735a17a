// Reading how a quadrotor's motors are powered (part of sim/scenario_loader.cpp): its battery
// and motor map (vehicles[i].battery, vehicles[i].motor_speed_map), and the Crazyflie firmware
// build's thrust path (controller.thrust_map, thrust_map_coefficients, idle_thrust, platform).
#include <string>

#include "control/controller_registry.h"
#include "sim/declared_key_reader.h"
#include "sim/scenario_sections.h"

namespace cosim {

void readVehiclePower(const YamlReader& r, const YAML::Node& n, const std::string& key,
                      VehicleSpec& v) {
  for (const char* k : {"battery", "motor_speed_map"})
    if (n[k] && v.kind == VehicleKind::GroundRobot)
      r.fail(n[k], key + "." + k, "applies to quadrotor models, not URDFs");
  if (n["motor_speed_map"]) {
    const Eigen::Vector3d c = r.vec3(n["motor_speed_map"], key + ".motor_speed_map");
    if (!(c[1] > 0.0))
      r.fail(n["motor_speed_map"], key + ".motor_speed_map",
             "c1 (rad/s per volt) must be positive: [c0, c1, c2]");
    v.motor_speed_map = c;
  }
  if (!n["battery"]) return;
  BatterySettings s;
  readDeclaredKeys(r, n["battery"], key + ".battery", s);
  v.battery = s;
}

CrazyflieThrustPath readCrazyflieThrustPath(const YamlReader& r, const YAML::Node& c,
                                            const std::string& prefix, const std::string& name) {
  CrazyflieThrustPath path;
  const std::string key = prefix + "controller";
  for (const char* k : {"thrust_map", "thrust_map_coefficients", "idle_thrust", "platform"})
    if (c[k] && !takesCrazyflieThrustPath(name))
      r.fail(c[k], key + "." + k,
             "applies to the crazyflie_lee, crazyflie_mellinger and crazyflie_pid controllers, "
             "not '" +
                 name + "'");
  if (c["thrust_map"]) {
    const auto map = crazyflieThrustMapNamed(r.text(c["thrust_map"], key + ".thrust_map"));
    if (!map)
      r.fail(c["thrust_map"], key + ".thrust_map",
             "must be 'battery_compensated' or 'pwm_quadratic'");
    path.map = *map;
  }
  if (c["thrust_map_coefficients"]) {
    if (path.map != CrazyflieThrustMap::PwmQuadratic)
      r.fail(c["thrust_map_coefficients"], key + ".thrust_map_coefficients",
             "applies to thrust_map: pwm_quadratic");
    path.pwm_quadratic = r.vec3(c["thrust_map_coefficients"], key + ".thrust_map_coefficients");
  }
  if (c["idle_thrust"])
    path.idle_thrust = r.number(c["idle_thrust"], key + ".idle_thrust", 0.0, 65535.0);
  if (c["platform"]) {
    const auto platform = crazyflieMixerPlatformNamed(r.text(c["platform"], key + ".platform"));
    if (!platform) r.fail(c["platform"], key + ".platform", "must be 'cf21bl' or 'cf2'");
    path.platform = *platform;
  }
  return path;
}

void checkVehiclePower(const YamlReader& r, const YAML::Node& root, Scenario& s) {
  bool robots = false;
  for (const VehicleSpec& v : s.vehicles) robots = robots || v.kind == VehicleKind::GroundRobot;
  // The quadrotors' controller: the aerial one when ground robots take the top-level one.
  const std::string& name = robots ? s.aerial.controller.name : s.motion.controller.name;
  const CrazyflieThrustPath& path =
      robots ? s.aerial.controller.thrust_path : s.motion.controller.thrust_path;
  for (std::size_t i = 0; i < s.vehicles.size(); ++i) {
    VehicleSpec& v = s.vehicles[i];
    if (v.kind != VehicleKind::Quadrotor) continue;
    const YAML::Node n = root["vehicles"][i];
    const std::string key = "vehicles[" + std::to_string(i) + "]";
    for (const char* k : {"battery", "motor_speed_map"})
      if (n[k] && !takesCrazyflieThrustPath(name))
        r.fail(n[k], key + "." + k,
               "applies to the crazyflie_* controllers (which drive their motors by PWM), not '" +
                   name + "'");
    // pwm_quadratic leaves the thrust to the battery's voltage: without a battery given, a
    // fresh one of the defaults (sim/battery.h).
    if (path.needsBattery() && !v.battery) v.battery = BatterySettings{};
  }
}

}  // namespace cosim
