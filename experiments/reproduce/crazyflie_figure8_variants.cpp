#include "experiments/reproduce/crazyflie_figure8_variants.h"

#include <sstream>
#include <stdexcept>
#include <vector>

#include "control/crazyflie_platform.h"
#include "sim/world_model.h"

namespace cosim::reproduce {

namespace {

bool off(const FigureEightVariant& v, FigureEightEffect e) {
  return (v.effects_off & e) != 0;
}

// The --set overrides that switch v's effects off where a scenario key says it.
std::vector<std::string> effectOverrides(const FigureEightVariant& v) {
  std::vector<std::string> o;
  // A battery that holds its voltage: no internal resistance (no sag under load) and a capacity
  // no flight drains, so the thrust no longer follows the battery. (Upstream's compensation,
  // controller.thrust_map: battery_compensated, is not that: its thrust curve is another
  // vehicle's, docs/crazyflie.md.)
  if (off(v, kBatterySag)) {
    o.push_back("vehicles[0].battery.internal_resistance=0");
    o.push_back("vehicles[0].battery.capacity_mah=1000000");
  }
  if (off(v, kFirmwareEstimator)) o.push_back("estimator.name=ekf");
  if (off(v, kMocapLatency)) {
    o.push_back("sensors.position.latency=0");
    o.push_back("sensors.attitude.latency=0");
  }
  if (off(v, kRotorDrag)) o.push_back("disturbances.rotor_drag=false");
  return o;
}

}  // namespace

Scenario figureEightScenario(const FigureEightVariant& v, double timescale, std::uint64_t seed) {
  std::ostringstream ts;
  ts << timescale;
  std::vector<std::string> overrides = {"vehicles[0].reference.timescale=" + ts.str(),
                                        "controller.name=" + std::string(v.controller),
                                        "sim.seed=" + std::to_string(seed)};
  for (std::string& o : effectOverrides(v)) overrides.push_back(std::move(o));
  Scenario s = loadScenario(COSIM_SCENARIOS_DIR "/crazyflie_figure8.yaml", overrides);
  VehicleSpec& cf = s.vehicles[0];
  if (off(v, kSensing)) {
    s.sensors = SensorSettings{};
    s.estimator.kind = EstimatorKind::GroundTruth;
  }
  if (off(v, kImuNoise)) {
    s.sensors.imu.noise = ImuNoise{};
    s.sensors.imu.gyro_bias_init = s.sensors.imu.accel_bias_init = 0.0;
    // The identified densities replace the scenario's for this vehicle: zero them too.
    if (cf.airframe.gyro_noise) cf.airframe.gyro_noise = 0.0;
    if (cf.airframe.accel_noise) cf.airframe.accel_noise = 0.0;
  }
  if (off(v, kMotorLag)) {
    // 0.1 ms: far below the 1 ms physics step, so a rotor reaches its command within one step.
    cf.airframe.time_constant_up = cf.airframe.time_constant_down = 1e-4;
    cf.airframe.motor_delay = 0.0;
  }
  if (v.firmware_default_mass)
    s.motion.controller.gains.set("mass", std::to_string(crazyflie21BrushlessPlatform().mass));
  return s;
}

std::string figureEightModelXml(const FigureEightVariant& v, const Scenario& s) {
  std::string xml = composeWorldXml(s);
  if (!off(v, kThrustLimit)) return xml;
  // No rotor speed limit: the model's constant replaced (the airframe file does not hold it).
  const std::string key = "name=\"cf/max_rotor_speed\" data=\"";
  const std::size_t at = xml.find(key);
  if (at == std::string::npos) throw std::logic_error("the model has no cf/max_rotor_speed");
  const std::size_t from = at + key.size();
  xml.replace(from, xml.find('"', from) - from, "100000");
  return xml;
}

}  // namespace cosim::reproduce
