// The air's effects on the quadrotors (sim/aerodynamics.h): per-rotor drag scaled by rotor speed
// and acting across the rotor axes only, ground effect against whatever lies under each rotor,
// and downwash from a vehicle above.
#include "sim/aerodynamics.h"
#include "sim/quadrotor_plant.h"

#include <gtest/gtest.h>

#include <cmath>

#include "control/geometric_controller.h"
#include "reference_flights.h"
#include "sim/downwash.h"
#include "sim/ground_effect.h"
#include "single_vehicle_scenario.h"

using namespace cosim;

namespace {

auto geometricWithoutIntegral() {
  return [](const QuadrotorParams& q) {
    GeometricGains gains;
    gains.k_i = 0.0;
    return std::make_unique<GeometricController>(q, gains);
  };
}

// Along-track error (reference minus actual, along x) averaged over the middle of the cruise.
double meanLagDuringCruise(const RunLog& log, const test::StraightLineReference& ref) {
  const double from = ref.cruiseStart() + 0.6 * (ref.cruiseEnd() - ref.cruiseStart());
  double sum = 0.0;
  int n = 0;
  for (const LogSample& x : log.vehicles[0].samples)
    if (x.t > from && x.t < ref.cruiseEnd()) sum += x.ref_pos.x() - x.pos.x(), ++n;
  return sum / n;
}

}  // namespace

TEST(RotorDrag, ACruiseLagsByTheDragOverThePositionGain) {
  // At a steady 4 m/s the four rotors drag -sum_i w_i c_d v = -m d v (d = 0.37 1/s for the Iris:
  // hover speed 794 rad/s, c_d 1.75e-4). Without integral action nor drag compensation the
  // geometric controller's position loop holds that force with a lag of d v / k_x.
  Scenario s = test::singleVehicleScenario({-9, 0, 3}, {9, 0, 3}, 8.0);
  s.disturbances.rotor_drag = true;
  test::StraightLineReference line({-9, 0, 3}, {9, 0, 3}, 4.0, 2.0);
  const RunLog log = test::flyAlong(s, {&line}, geometricWithoutIntegral());
  const QuadrotorParams p = WorldModel::build(s).vehicles()[0].params;
  const double expected = p.linearDragPerMass().x() * 4.0 / GeometricGains{}.k_x.x();
  EXPECT_NEAR(expected, 0.247, 0.005);  // the Iris' numbers, worked out in the comment above
  // Tilting into the drag spins the rotors 1 % faster and turns v_perp by cos(tilt): within 5 %.
  EXPECT_NEAR(meanLagDuringCruise(log, line), expected, 0.05 * expected);
}

TEST(RotorDrag, ScalesWithRotorSpeedAndActsAtTheRotors) {
  // A cf2 moving at 4 m/s along x, level: each rotor drags -w c_d v (gym-pybullet-drones'
  // c_d = 9.1785e-7 for it), so the force doubles when the rotors spin twice as fast, and since
  // it acts at the rotor hubs, 1 cm above the centre of mass, it pitches the vehicle by
  // 0.01 m x F (which is why, without an attitude integrator, a cf2 cruises a few degrees off
  // the attitude its controller asks for).
  Scenario s = test::singleVehicleScenario({0, 0, 3}, {0, 0, 3}, 1.0, "cf2");
  s.disturbances.rotor_drag = true;
  const WorldModel world = WorldModel::build(s);
  const VehicleHandles& v = world.vehicles()[0];
  mjData* d = mj_makeData(world.model());
  mj_resetData(world.model(), d);
  d->qvel[v.qvel_adr] = 4.0;
  mj_forward(world.model(), d);
  Aerodynamics air(s.disturbances, world, 1);
  QuadrotorPlant plant(v, SensorSettings{}, 1, 0);
  const auto dragAt = [&](double w) {
    plant.rotors().reset(Eigen::Vector4d::Constant(w));
    air.apply(world.model(), d, {&plant}, 0.001);
    // The free joint's generalized force: world force, body moment; level, so the body y axis is
    // the world's. The equal rotors' own moments cancel, their thrust is vertical.
    const mjtNum* f = d->qfrc_applied + v.qvel_adr;
    return std::pair{Eigen::Vector3d(f[0], f[1], 0.0), Eigen::Vector3d(f[3], f[4], f[5])};
  };
  const auto [slow_force, slow_torque] = dragAt(800.0);
  const auto [fast_force, fast_torque] = dragAt(1600.0);
  EXPECT_NEAR(slow_force.x(), -4 * 800.0 * 9.1785e-7 * 4.0, 1e-12);
  EXPECT_NEAR(fast_force.x() / slow_force.x(), 2.0, 1e-12);
  EXPECT_NEAR(slow_force.y(), 0.0, 1e-15);
  // Each rotor adds r x F = (0, 0.01 F_x, -y_i F_x); the y_i cancel over the four rotors.
  EXPECT_NEAR(slow_torque.y(), 0.01 * slow_force.x(), 1e-15);
  mj_deleteData(d);
}

TEST(RotorDrag, ActsOnlyAcrossTheRotorAxes) {
  // A vertical climb at 2 m/s: the air flows along the rotor axes, so rotor drag adds nothing
  // and the flight is the same as without it.
  const auto climb = [](bool drag) {
    Scenario s = test::singleVehicleScenario({0, 0, 1}, {0, 0, 8}, 5.0);
    s.disturbances.rotor_drag = drag;
    test::StraightLineReference line({0, 0, 1}, {0, 0, 8}, 2.0, 2.0);
    return test::flyAlong(s, {&line}, geometricWithoutIntegral());
  };
  const RunLog with = climb(true), without = climb(false);
  ASSERT_EQ(with.vehicles[0].samples.size(), without.vehicles[0].samples.size());
  double differ = 0.0;
  for (std::size_t i = 0; i < with.vehicles[0].samples.size(); ++i)
    differ = std::max(
        differ, (with.vehicles[0].samples[i].pos - without.vehicles[0].samples[i].pos).norm());
  EXPECT_LT(differ, 1e-9);
}

TEST(GroundEffect, ActsOnTheRotorsOverASurfaceAndNotTheOthers) {
  // A quad_1500g hovering with its rear rotors 0.2 m over a box top and its front rotors 1.2 m
  // over the floor: only the rear rotors gain (Cheeseman-Bennett, R = 0.128 m).
  Scenario s = test::singleVehicleScenario({0.0, 0, 1.2}, {0.0, 0, 1.2}, 1.0);
  Obstacle box;
  box.type = ObstacleType::Box;
  box.pos = {-2.0, 0.0, 0.5};  // its top at z = 1, its front face at x = -0.0
  box.size = {4.0, 4.0, 1.0};
  s.world.obstacles.push_back(box);
  s.vehicles[0].start = {0.0, 0, 1.2};
  s.disturbances.ground_effect = true;
  const WorldModel world = WorldModel::build(s);
  mjData* d = mj_makeData(world.model());
  mj_resetData(world.model(), d);
  mj_forward(world.model(), d);
  QuadrotorPlant plant(world.vehicles()[0], SensorSettings{}, 1, 0);
  plant.rotors().reset(Eigen::Vector4d::Constant(world.vehicles()[0].params.hoverRotorSpeed()));
  Aerodynamics air(s.disturbances, world, 1);
  air.apply(world.model(), d, {&plant}, 0.001);
  const double R = 0.128;
  // Rotors 1 and 2 are the rear ones (x = -0.13), their hubs 0.2 + 0.023 m over the top.
  const double over_box = 1.0 / (1.0 - std::pow(R / (4.0 * 0.223), 2));
  EXPECT_NEAR(air.thrustFactor(0, 1), over_box, 1e-6);
  EXPECT_NEAR(air.thrustFactor(0, 2), over_box, 1e-6);
  // The front ones look 1.223 m down to the floor, beyond the 5 R the ray looks: no gain.
  EXPECT_DOUBLE_EQ(air.thrustFactor(0, 0), 1.0);
  EXPECT_DOUBLE_EQ(air.thrustFactor(0, 3), 1.0);
  // The gain reaches MuJoCo as thrust: the rear rotors push harder by it, which pitches the
  // vehicle nose down (a positive moment about body y, -sum x_i T_i; the rear is at x = -0.13 m).
  EXPECT_NEAR(plant.appliedThrusts()[1] / plant.appliedThrusts()[0], over_box, 1e-9);
  const double T = plant.appliedThrusts()[0];
  EXPECT_NEAR(d->qfrc_applied[world.vehicles()[0].qvel_adr + 4],
              -(2 * -0.13 * T * over_box + 2 * 0.13 * T), 1e-9);
  mj_deleteData(d);
}

TEST(Downwash, TheWakeCarriesTheRotorsThrustAsMomentumFlux) {
  // The jet's momentum flux, rho * integral of u^2 over a cross-section, is the rotor's thrust
  // (momentum theory; a free jet keeps its momentum flux): all of it in the near field, 86 % in
  // the far field with Pope's B and S and a Gaussian profile. A wrong exit velocity or width
  // would be far off.
  const double T = 3.7, R = 0.128;
  for (auto [dz, kept] : {std::pair{0.3, 1.0}, std::pair{3.0, 0.86}}) {
    double flux = 0.0;
    const double dr = 1e-4;
    for (double r = 0.5 * dr; r < 2.0; r += dr) {
      const double u = rotorWakeVelocity(T, R, dz, r);
      flux += kAirDensity * u * u * 2.0 * M_PI * r * dr;
    }
    EXPECT_NEAR(flux / T, kept, 0.02) << dz;
  }
  // Just under the disc: the fully contracted slipstream, 2 v_i = 2 sqrt(T / (2 rho A)).
  EXPECT_NEAR(rotorWakeVelocity(T, R, 0.01, 0.0),
              2.0 * std::sqrt(T / (2 * kAirDensity * M_PI * R * R)), 1e-9);
  EXPECT_DOUBLE_EQ(rotorWakeVelocity(T, R, -0.5, 0.0), 0.0);  // nothing blows upwards
}

TEST(Downwash, AQuadUnderAnotherTracksAtLeastTwiceAsBadly) {
  // Two quad_1500g fly the same 12 m line at 2 m/s, one 1.0 m directly under the other.
  const auto fly = [](bool downwash) {
    Scenario s = test::singleVehicleScenario({-6, 0, 4}, {6, 0, 4}, 9.0);
    VehicleSpec lower = s.vehicles[0];
    lower.name = "uav2";
    lower.start = {-6, 0, 3};
    lower.waypoints = {{6, 0, 3}};
    s.vehicles.push_back(lower);
    s.disturbances.downwash = downwash;
    test::StraightLineReference upper_line({-6, 0, 4}, {6, 0, 4}, 2.0, 1.0);
    test::StraightLineReference lower_line({-6, 0, 3}, {6, 0, 3}, 2.0, 1.0);
    return test::flyAlong(s, {&upper_line, &lower_line}, [](const QuadrotorParams& q) {
      return std::make_unique<GeometricController>(q, GeometricGains{});
    });
  };
  const auto maxError = [](const VehicleLog& v) {
    double e = 0.0;
    for (const LogSample& x : v.samples) e = std::max(e, (x.pos - x.ref_pos).norm());
    return e;
  };
  const RunLog off = fly(false), on = fly(true);
  ASSERT_EQ(on.end_reason, RunEnd::MaxTime);
  const double lower_off = maxError(off.vehicles[1]), lower_on = maxError(on.vehicles[1]);
  EXPECT_GE(lower_on, 2.0 * lower_off) << lower_on << " vs " << lower_off;
  // The upper vehicle is not disturbed: its error is the same either way.
  EXPECT_NEAR(maxError(on.vehicles[0]), maxError(off.vehicles[0]), 1e-6);
}
