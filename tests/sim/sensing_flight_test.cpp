// Flights that sense themselves: the scenario's sensing sections, the controller flying on the
// EKF's estimate, repeatable noise, and a model error that shows as the offset its size predicts.
#include <gtest/gtest.h>

#include <cmath>

#include "control/geometric_controller.h"
#include "sim/flight_metrics.h"
#include "sim/sensors/sensor_presets.h"
#include "single_vehicle_scenario.h"

using namespace cosim;

namespace {

const char* const kScenario =
    "world: {bounds: {min: [0, 0, 0], max: [20, 20, 6]}}\n"
    "vehicles: [{name: uav1, model: quad_1500g, start: [2, 2, 2], goal: [18, 18, 3]}]\n";

Scenario hoverWith(const std::string& preset, double seconds, std::uint64_t seed = 1) {
  Scenario s = test::singleVehicleScenario({0, 0, 3}, {2, 1, 3}, seconds);
  s.sensors = sensorPreset(preset);
  s.estimator.kind = preset == "ideal" ? EstimatorKind::GroundTruth : EstimatorKind::Ekf;
  s.sim.seed = seed;
  return s;
}

RunLog flyGeometric(const Scenario& s, double k_i = GeometricGains{}.k_i) {
  return test::flyWholeTime(s, [k_i](const QuadrotorParams& q) {
    GeometricGains g;
    g.k_i = k_i;
    return std::make_unique<GeometricController>(q, g);
  });
}

}  // namespace

TEST(SensingSections, APresetChoosesTheEkfAndBlocksChangeItsValues) {
  const Scenario a = parseScenario(std::string(kScenario) + "sensors: {preset: mocap}\n", "t.yaml");
  EXPECT_EQ(a.estimator.kind, EstimatorKind::Ekf);
  EXPECT_TRUE(a.sensors.imu.present && a.sensors.position.present && a.sensors.attitude.present);
  EXPECT_DOUBLE_EQ(a.sensors.position.noise, sensorPreset("mocap").position.noise);
  const Scenario b = parseScenario(
      std::string(kScenario) + "sensors: {preset: onboard, position: {noise: 0.2}}\n", "t.yaml");
  EXPECT_FALSE(b.sensors.attitude.present);  // GPS-class sensing has no attitude fix
  EXPECT_DOUBLE_EQ(b.sensors.position.noise, 0.2);
  EXPECT_DOUBLE_EQ(b.sensors.position.rate, sensorPreset("onboard").position.rate);
  const Scenario c = parseScenario(kScenario, "t.yaml");
  EXPECT_TRUE(c.sensors.ideal());
  EXPECT_EQ(c.estimator.kind, EstimatorKind::GroundTruth);
  const Scenario d = parseScenario(
      std::string(kScenario) + "sensors: {preset: mocap}\nestimator: {name: ground_truth}\n",
      "t.yaml");
  EXPECT_EQ(d.estimator.kind, EstimatorKind::GroundTruth);
}

TEST(SensingFlight, TheControllerFliesOnAnEstimateAsGoodAsItsSensors) {
  // Predicting at every IMU sample, the estimate the controller sees is of the present: its error
  // is the filter's own.
  const auto estimation = [](const std::string& preset) {
    Scenario s = hoverWith(preset, 12.0);
    s.estimator.predict_rate = s.sensors.imu.rate;
    const RunLog log = flyGeometric(s);
    EXPECT_EQ(log.end_reason, RunEnd::MaxTime) << preset;
    return computeFlightMetrics(log.vehicles[0], World{}, ErrorReference::PlannedPath)
        .estimation_rmse_m;
  };
  const double ideal = estimation("ideal"), mocap = estimation("mocap"),
               onboard = estimation("onboard");
  EXPECT_EQ(ideal, 0.0);   // the controller saw the truth
  EXPECT_GT(mocap, 1e-4);  // 1 mm fixes, fused: a fraction of a millimetre
  EXPECT_LT(mocap, 2e-3);
  EXPECT_GT(onboard, 0.05);  // 0.5 m GPS fixes at 10 Hz: decimetres
  EXPECT_LT(onboard, 0.5);
}

TEST(SensingFlight, PredictingAt100HzTheControllerSeesTheEstimateOfTheLatestPrediction) {
  // At the default 100 Hz the controller is handed the estimate of the latest prediction, made
  // `age` = t mod 10 ms ago: its error against the present truth adds the motion since,
  // velocity x age, to the filter's own error (nearly independent of it).
  Scenario every = hoverWith("mocap", 12.0), at100 = hoverWith("mocap", 12.0);
  every.estimator.predict_rate = every.sensors.imu.rate;
  ASSERT_DOUBLE_EQ(at100.estimator.predict_rate, 100.0);
  const double own =
      computeFlightMetrics(flyGeometric(every).vehicles[0], World{}, ErrorReference::PlannedPath)
          .estimation_rmse_m;
  const RunLog log = flyGeometric(at100);
  const double seen =
      computeFlightMetrics(log.vehicles[0], World{}, ErrorReference::PlannedPath).estimation_rmse_m;
  double motion_sq = 0.0;
  for (const LogSample& x : log.vehicles[0].samples) {
    const double age = std::fmod(x.t + 1e-9, 0.01) - 1e-9;
    motion_sq += (x.vel * age).squaredNorm();
  }
  motion_sq /= static_cast<double>(log.vehicles[0].samples.size());
  const double expected = std::sqrt(own * own + motion_sq);
  EXPECT_GT(std::sqrt(motion_sq), own);  // the age matters here: more than the filter's error
  EXPECT_NEAR(seen, expected, 0.05 * expected);
}

TEST(SensingFlight, NoiseIsRepeatableUnderTheSameSeedAndDiffersUnderAnother) {
  const RunLog a = flyGeometric(hoverWith("mocap", 3.0, 7));
  const RunLog b = flyGeometric(hoverWith("mocap", 3.0, 7));
  const RunLog c = flyGeometric(hoverWith("mocap", 3.0, 8));
  ASSERT_EQ(a.vehicles[0].samples.size(), b.vehicles[0].samples.size());
  double same = 0.0, other = 0.0;
  for (std::size_t i = 0; i < a.vehicles[0].samples.size(); ++i) {
    same = std::max(same,
                    (a.vehicles[0].samples[i].est_pos - b.vehicles[0].samples[i].est_pos).norm());
    other = std::max(other,
                     (a.vehicles[0].samples[i].est_pos - c.vehicles[0].samples[i].est_pos).norm());
  }
  EXPECT_EQ(same, 0.0);
  EXPECT_GT(other, 1e-4);
}

TEST(ModelError, AnUnderratedRotorHoversAboveItsSetPointByTheLoopGain) {
  // The software believes k_f 5 % lower than the truth: each command makes T / 0.95. Without
  // integral action the hover settles where m (g - k_z e_z) = 0.95 m g, i.e. e_z = 0.05 g / k_z
  // = 6.1 cm above the set-point; a 5 % heavier belief gives e_z = (1 - 1/1.05) g / k_z = 5.8 cm.
  const auto offset = [](const ModelError& e) {
    Scenario s = test::singleVehicleScenario({0, 0, 3}, {0, 0, 3}, 6.0);
    s.model_error = e;
    const WorldModel world = WorldModel::build(s);
    const QuadrotorParams believed = believedAirframe(world.vehicles()[0].params, e);
    GeometricGains g;
    g.k_i = 0.0;
    GeometricController controller(believed, g);
    WaypointReference reference({{0, 0, 3}}, 0.0);
    std::vector<VehiclePilot> pilots(1);
    pilots[0].controller = &controller;
    pilots[0].reference = &reference;
    pilots[0].goal = {0, 0, 3};
    pilots[0].believed_airframe = &believed;
    FlightOptions o;
    o.settings = s.sim;
    o.hold_after_arrival = 1e9;
    return simulateFlight(world, s, pilots, o).vehicles[0].samples.back().pos.z() - 3.0;
  };
  const double k_z = GeometricGains{}.k_x.z();
  EXPECT_NEAR(offset({1.0, 1.0, 0.95}), 0.05 * 9.81 / k_z, 2e-3);
  EXPECT_NEAR(offset({1.05, 1.0, 1.0}), (1.0 - 1.0 / 1.05) * 9.81 / k_z, 2e-3);
  EXPECT_NEAR(offset({}), 0.0, 1e-4);
}
