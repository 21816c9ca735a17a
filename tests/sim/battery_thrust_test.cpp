// A Crazyflie on a battery: the LiPo's voltage over charge and current, and a Lee-controlled hover
// under the two firmware thrust maps (the fork's pwm_quadratic, whose thrust follows the battery,
// and upstream's battery_compensated, whose does not), against the hover worked by hand; and
// what the loader accepts and refuses of the battery, motor map and thrust-path keys.
#include <gtest/gtest.h>

#include "control/crazyflie_lee_controller.h"
#include "core/input_error.h"
#include "sim/battery.h"
#include "sim/scenario.h"
#include "sim/world_model.h"
#include "tests/sim/single_vehicle_scenario.h"

namespace cosim {
namespace {

TEST(LipoBattery, VoltageFollowsTheFirmwaresChargeCurveAndTheInternalResistance) {
  // pm_stm32f4.c LiPoTypicalChargeCurve: 3.92 V at 50 %, 3.96 V at 60 %; 4.2 V full, 3.0 empty.
  EXPECT_NEAR(LipoBattery::openCircuitVoltage(0.55), 3.94, 1e-12);
  EXPECT_NEAR(LipoBattery::openCircuitVoltage(1.0), 4.20, 1e-12);
  EXPECT_NEAR(LipoBattery::openCircuitVoltage(0.0), 3.00, 1e-12);
  EXPECT_NEAR(LipoBattery::openCircuitVoltage(0.05), 3.39, 1e-12);
  BatterySettings s;
  s.state_of_charge = 0.55;
  LipoBattery b(s);
  // 2 A through 0.085 ohm: 3.94 - 0.17 = 3.77 V; drawing 7.54 W (2 A at 3.77 V) the same root.
  EXPECT_NEAR(b.terminalVoltage(2.0), 3.77, 1e-12);
  EXPECT_NEAR(b.terminalVoltageAtPower(7.54), 3.77, 1e-12);
  // 2 A for 63 s is 126 C, a tenth of 350 mAh (1260 C): 55 % -> 45 %, 3.89 + 0.5 x 0.03 V.
  b.drain(2.0, 63.0);
  EXPECT_NEAR(b.stateOfCharge(), 0.45, 1e-12);
  EXPECT_NEAR(b.terminalVoltage(0.0), 3.905, 1e-12);
}

// Hovers a 37 g cf21_brushless at 1 m for 8 s under crazyflie_lee on a battery that holds its
// charge (1e6 mAh) at `state_of_charge`; the height it settles at.
double hoverHeight(CrazyflieThrustMap map, double state_of_charge,
                   const Eigen::Vector3d* motor_map = nullptr) {
  Scenario s = test::singleVehicleScenario({0, 0, 1}, {0, 0, 1}, 8.0, "cf21_brushless");
  s.vehicles[0].mass = 0.037;
  BatterySettings b;
  b.capacity_mah = 1e6;
  b.state_of_charge = state_of_charge;
  s.vehicles[0].battery = b;
  if (motor_map) s.vehicles[0].motor_speed_map = *motor_map;
  CrazyflieThrustPath path;
  path.map = map;
  const RunLog log = test::flyWholeTime(s, [&](const QuadrotorParams& q) {
    auto c = std::make_unique<CrazyflieLeeController>(q, CrazyflieLeeGains{});
    c->setThrustPath(path);
    return c;
  });
  return log.vehicles[0].samples.back().pos.z();
}

TEST(BatteryThrust, WithoutCompensationLeeHoversWhereKposPMakesUpTheThrustDeficit) {
  // By hand: the rotors hover at w_h = sqrt(m g / 4 k_f) = 1533.25 rad/s, drawing
  // 4 (k_m/k_f) k_f w_h^3 / 0.5 = 6.336 W, so the terminal voltage is
  // (OCV + sqrt(OCV^2 - 4 0.085 6.336)) / 2: 3.7774 V at 50 % (OCV 3.92), 3.9641 V at 90 % (4.10).
  // Lee (Kpos_P 7, no integral) commands T = m (g + 7 e_z); the fork's duty for T/4 in grams on
  // the motor map at that voltage makes 4 k_f w^2 = m g at e_z = +0.022623 m (sinks 2.26 cm) at
  // 50 % and e_z = -0.085240 m (8.52 cm above) at 90 %.
  EXPECT_NEAR(hoverHeight(CrazyflieThrustMap::PwmQuadratic, 0.5), 1.0 - 0.022623, 1e-3);
  EXPECT_NEAR(hoverHeight(CrazyflieThrustMap::PwmQuadratic, 0.9), 1.0 + 0.085240, 1e-3);
}

TEST(BatteryThrust, WithCompensationTheHoverDoesNotMoveAsTheBatterySags) {
  // A motor map that agrees with the upstream thrust curve (the 2026 guards stand's line,
  // 350.091 + 613.488 v rad/s): VMOTOR2THRUST's voltage for T/4 on it hovers at e_z = -0.014916 m
  // whatever the battery's voltage.
  const Eigen::Vector3d line(350.091, 613.488, 0.0);
  const double full = hoverHeight(CrazyflieThrustMap::BatteryCompensated, 0.9, &line);
  const double low = hoverHeight(CrazyflieThrustMap::BatteryCompensated, 0.3, &line);
  EXPECT_NEAR(full, 1.014916, 1e-3);
  EXPECT_NEAR(low, full, 1e-4);
}

const char* kCrazyflie = R"(world:
  bounds: {min: [-2, -2, 0], max: [2, 2, 2]}
vehicles:
  - {name: cf, model: cf21_brushless, mass: 0.037, start: [0, 0, 1], goal: [0, 0, 1]}
controller: {name: crazyflie_lee}
sim: {control_rate: 500}
)";

std::string errorOf(const std::string& text) {
  try {
    const Scenario s = parseScenario(text, "s.yaml", {});
    WorldModel::build(s);
  } catch (const InputError& e) {
    return e.place() + " | " + e.problem();
  }
  return "";
}

std::string with(std::string s, const std::string& from, const std::string& to) {
  return s.replace(s.find(from), from.size(), to);
}

TEST(BatteryThrust, LoaderReadsTheThrustPathAndGivesPwmQuadraticADefaultBattery) {
  const Scenario s = parseScenario(
      with(kCrazyflie, "{name: crazyflie_lee}",
           "{name: crazyflie_lee, thrust_map: pwm_quadratic, platform: cf2, idle_thrust: 7000, "
           "thrust_map_coefficients: [0.1, 0.02, 0.0002]}"),
      "s.yaml", {});
  EXPECT_EQ(s.motion.controller.thrust_path.map, CrazyflieThrustMap::PwmQuadratic);
  EXPECT_EQ(s.motion.controller.thrust_path.platform, CrazyflieMixerPlatform::Cf2);
  EXPECT_EQ(s.motion.controller.thrust_path.idleThrust(), 7000.0);
  EXPECT_EQ(s.motion.controller.thrust_path.pwm_quadratic, Eigen::Vector3d(0.1, 0.02, 0.0002));
  ASSERT_TRUE(s.vehicles[0].battery.has_value());
  EXPECT_EQ(s.vehicles[0].battery->capacity_mah, 350.0);
  EXPECT_EQ(s.vehicles[0].battery->state_of_charge, 1.0);
  const Scenario b = parseScenario(
      with(kCrazyflie, "goal: [0, 0, 1]}",
           "goal: [0, 0, 1], battery: {state_of_charge: 0.4, internal_resistance: 0.1}}"),
      "s.yaml", {});
  EXPECT_EQ(b.vehicles[0].battery->state_of_charge, 0.4);
  EXPECT_EQ(b.vehicles[0].battery->internal_resistance, 0.1);
  EXPECT_EQ(b.motion.controller.thrust_path.map, CrazyflieThrustMap::BatteryCompensated);
}

TEST(BatteryThrust, LoaderRefusesBadThrustPathAndBatteryKeys) {
  const auto expect = [](const std::string& text, const std::string& place) {
    const std::string e = errorOf(text);
    EXPECT_NE(e.find(place), std::string::npos) << e;
  };
  expect(with(kCrazyflie, "crazyflie_lee}", "crazyflie_lee, thrust_map: quadratic}"),
         "controller.thrust_map");
  expect(with(kCrazyflie, "crazyflie_lee}", "crazyflie_lee, platform: cf3}"),
         "controller.platform");
  expect(with(kCrazyflie, "crazyflie_lee}", "crazyflie_lee, idle_thrust: 70000}"),
         "controller.idle_thrust");
  expect(with(kCrazyflie, "crazyflie_lee}", "crazyflie_lee, thrust_map_coefficients: [1, 2, 3]}"),
         "controller.thrust_map_coefficients");  // only with pwm_quadratic
  expect(with(kCrazyflie, "{name: crazyflie_lee}", "{name: geometric, thrust_map: pwm_quadratic}"),
         "controller.thrust_map");
  expect(with(kCrazyflie, "goal: [0, 0, 1]}", "goal: [0, 0, 1], battery: {state_of_charge: 2}}"),
         "vehicles[0].battery.state_of_charge");
  expect(with(kCrazyflie, "goal: [0, 0, 1]}", "goal: [0, 0, 1], battery: {volts: 4}}"),
         "vehicles[0].battery");
  expect(with(kCrazyflie, "goal: [0, 0, 1]}", "goal: [0, 0, 1], motor_speed_map: [0, -1, 0]}"),
         "vehicles[0].motor_speed_map");
  expect(with(with(kCrazyflie, "goal: [0, 0, 1]}", "goal: [0, 0, 1], battery: {}}"),
              "{name: crazyflie_lee}", "{name: geometric}"),
         "vehicles[0].battery");
  // A model without a motor map cannot fly on a battery unless the scenario gives one.
  expect(with(with(kCrazyflie, "goal: [0, 0, 1]}", "goal: [0, 0, 1], battery: {}}"),
              "cf21_brushless", "cf2"),
         "vehicles[0]");
  EXPECT_EQ(errorOf(with(with(kCrazyflie, "goal: [0, 0, 1]}",
                              "goal: [0, 0, 1], battery: {}, motor_speed_map: [0, 1000, 0]}"),
                         "cf21_brushless", "cf2")),
            "");
}

}  // namespace
}  // namespace cosim
