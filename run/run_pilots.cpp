#include "run/run_pilots.h"

#include <cmath>

#include "control/controller_factory.h"
#include "control/ground_feedback_linearization.h"
#include "control/ground_velocity_tracker.h"
#include "control/piecewise_polynomial_reference.h"

namespace cosim {

namespace {

// The gains of each ground controller, as controller.gains gives them.
GroundMotionLimits readGroundLimits(ParamSet& gains) {
  GroundMotionLimits limits;
  limits.max_acceleration = gains.getDouble("max_acceleration", 1.0, 1e-3, 100.0);
  limits.max_yaw_acceleration = gains.getDouble("max_yaw_acceleration", 4.0, 1e-3, 1000.0);
  return limits;
}

GroundVelocityTrackerGains readTrackerGains(ParamSet& gains) {
  GroundVelocityTrackerGains g;
  g.k_position = gains.getDouble("k_position", g.k_position, 1e-3, 100.0);
  g.k_yaw = gains.getDouble("k_yaw", g.k_yaw, 1e-3, 100.0);
  return g;
}

GroundFeedbackLinearizationParams readLinearizationGains(ParamSet& gains) {
  GroundFeedbackLinearizationParams p;
  p.b = gains.getDouble("b", p.b, 1e-3, 10.0);
  p.k = gains.getDouble("k", p.k, 1e-3, 100.0);
  return p;
}

// A holonomic base tracks its timed path with the velocity tracker; a differential drive with
// feedback linearization about a point ahead of its axle.
std::unique_ptr<GroundController> makeGroundController(ParamSet& gains, const VehicleHandles& h) {
  GroundMotionLimits limits = readGroundLimits(gains);
  limits.max_speed = h.drive.max_speed;
  limits.max_yaw_rate = h.drive.max_yaw_rate;
  if (h.drive.kind == GroundDrive::Kind::Holonomic)
    return std::make_unique<GroundVelocityTracker>(limits, readTrackerGains(gains));
  GroundFeedbackLinearizationParams p = readLinearizationGains(gains);
  p.wheel_separation = h.drive.wheel_separation;
  return std::make_unique<GroundFeedbackLinearization>(limits, p);
}

void buildRobotPilots(const Scenario& s, const RunSetup& setup, const WorldModel& world,
                      RobotPlans& plans, RunPilots& pilots, bool drivable) {
  for (std::size_t k = 0; k < setup.robots.size(); ++k) {
    ParamSet gains = setup.robot_sections.controller.gains;
    pilots.robot_controllers.push_back(
        makeGroundController(gains, world.vehicles()[setup.robots[k]]));
    gains.requireAllUsed("controller.gains (ground robots)");
    if (!drivable) continue;
    const VehicleSpec& spec = s.vehicles[setup.robots[k]];
    GroundPilot& pilot = pilots.robots.emplace_back();
    pilot.controller = pilots.robot_controllers.back().get();
    pilot.path = &plans.paths[k];
    pilot.yaw = spec.yaw_deg * M_PI / 180.0;
    pilot.goal = floorPoint(planarPoint(spec.goal()));
    for (const auto& p : plans.paths[k].points()) pilot.planned_path.push_back(floorPoint(p));
  }
}

void buildQuadrotorPilots(const Scenario& s, const RunSetup& setup, QuadrotorPlans& plans,
                          RunPilots& pilots, bool drivable) {
  const ControllerSection& controller = setup.quadrotor_sections.controller;
  for (std::size_t k = 0; k < setup.quadrotors.size(); ++k) {
    ParamSet gains = controller.gains;
    pilots.quadrotor_controllers.push_back(
        makeFlightController(controller.name, gains, plans.airframes[k],
                             controller.drag_compensation, controller.thrust_path));
    if (!drivable) continue;
    VehiclePilot& pilot = pilots.quadrotors.emplace_back();
    pilot.believed_airframe = &plans.airframes[k];
    pilot.controller = pilots.quadrotor_controllers.back().get();
    pilot.reference = plans.references[k].get();
    pilot.goal = s.vehicles[setup.quadrotors[k]].goal();
    pilot.planned_path = plans.plans[k].path.waypoints;
    if (const auto& given = s.vehicles[setup.quadrotors[k]].reference)
      pilot.reference_end = given->duration();
  }
}

}  // namespace

void checkGroundControllerGains(ParamSet gains) {
  readGroundLimits(gains);
  readTrackerGains(gains);
  readLinearizationGains(gains);
  gains.requireAllUsed("controller.gains (ground robots)");
}

RunPilots buildPilots(const Scenario& scenario, const RunSetup& setup, const WorldModel& world,
                      RunPlan& plan) {
  RunPilots pilots;
  buildRobotPilots(scenario, setup, world, plan.robots, pilots, plan.drivable());
  buildQuadrotorPilots(scenario, setup, plan.quadrotors, pilots, plan.drivable());
  return pilots;
}

}  // namespace cosim
