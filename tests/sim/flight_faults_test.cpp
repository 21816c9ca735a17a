// Faults in flight end the run with a reason instead of a log of nonsense: NaN controls (MuJoCo
// would zero them, or reset the state, and carry on), and a mixer saturated for too long.
#include <gtest/gtest.h>
#include <mujoco/mujoco.h>

#include <cmath>
#include <limits>

#include "control/waypoint_reference.h"
#include "sim/flight_simulation.h"
#include "sim/world_model.h"
#include "tests/sim/single_vehicle_scenario.h"

using namespace cosim;

namespace {

// Holds the hover thrust; reports the mixer as saturated while `saturated(t)` says so, and
// commands NaN from `nan_after` on.
class ScriptedController : public FlightController {
 public:
  ScriptedController(double hover_thrust, bool (*saturated)(double), double nan_after)
      : hover_(hover_thrust), saturated_(saturated), nan_after_(nan_after) {}
  std::string name() const override { return "scripted"; }
  void reset() override { t_ = 0.0; }
  ControlOutput update(const VehicleState&, const FlatReference&, double dt) override {
    ControlOutput out;
    out.rotor_thrusts.setConstant(t_ >= nan_after_ ? std::numeric_limits<double>::quiet_NaN()
                                                   : hover_);
    out.saturated = saturated_(t_);
    t_ += dt;
    return out;
  }

 private:
  double hover_;
  bool (*saturated_)(double);
  double nan_after_;
  double t_ = 0.0;
};

RunLog fly(double seconds, bool (*saturated)(double), double nan_after = 1e9) {
  // Only a fault or max_time ends the run.
  return test::flyWholeTime(
      test::singleVehicleScenario({0, 0, 2}, {0, 0, 2}, seconds), [&](const QuadrotorParams& q) {
        return std::make_unique<ScriptedController>(q.mass * q.gravity / 4.0, saturated, nan_after);
      });
}

}  // namespace

TEST(FlightFaults, MixerSaturatedWithoutABreakEndsTheRunJustAfterTheLimit) {
  const RunLog log = fly(10.0, [](double) { return true; });
  EXPECT_EQ(log.end_reason, RunEnd::Saturated);
  // The limit is 2 s of continuous saturation, checked at the 500 Hz control rate.
  EXPECT_NEAR(log.sim_time, 2.0, 0.01);
}

TEST(FlightFaults, SaturationWithBreaksShorterThanTheLimitDoesNotEndTheRun) {
  // Saturated 1.5 s out of every 2 s: never 2 s in a row.
  const RunLog log = fly(6.0, [](double t) { return std::fmod(t, 2.0) < 1.5; });
  EXPECT_EQ(log.end_reason, RunEnd::MaxTime);
  EXPECT_NEAR(log.sim_time, 6.0, 0.01);
}

// MuJoCo's warnings come here instead of going to its default (stdout and MUJOCO_LOG.TXT in the
// current folder).
std::string g_mujoco_warning;
extern "C" void recordWarning(const char* text) {
  g_mujoco_warning = text;
}

TEST(FlightFaults, NanRotorCommandsEndTheRunAsUnstableInsteadOfFlyingOn) {
  g_mujoco_warning.clear();
  mju_user_warning = recordWarning;
  const RunLog log = fly(
      5.0, [](double) { return false; }, 1.0);
  mju_user_warning = nullptr;
  // The NaN commands become NaN rotor speeds and thrusts, which MuJoCo's acceleration check
  // finds (it would reset the state and go on).
  EXPECT_NE(g_mujoco_warning.find("QACC"), std::string::npos) << g_mujoco_warning;
  EXPECT_EQ(log.end_reason, RunEnd::Unstable);
  EXPECT_GE(log.mujoco_warnings, 1);
  EXPECT_LT(log.sim_time, 1.01);
}
