#pragma once
// The planning stage of a run: every vehicle's plan, from the robots' top-level planner
// (run/robot_plans.h) and the quadrotors' planner (run/quadrotor_plans.h), and whether the run
// can be simulated.
#include <string>
#include <vector>

#include "run/group_plan.h"
#include "run/quadrotor_plans.h"
#include "run/record/plan_verification_report.h"
#include "run/record/run_setup.h"
#include "run/robot_plans.h"
#include "run/run_events.h"

namespace cosim {

struct RunRequest;

struct RunPlan {
  PlanStatus status = PlanStatus::Ready;
  std::string message;  // why it is not Ready: the robots' failure first, then the quadrotors'
  RobotPlans robots;    // empty in a run without robots
  QuadrotorPlans quadrotors;  // empty in a run without quadrotors
  // A quadrotor team's plan flown before it was trusted (run/team_plan_verification.h).
  PlanVerificationReport verification;

  bool drivable() const { return cosim::drivable(status); }
  // The planner's figures of the vehicles the top-level sections drive (RunSetup::primary).
  const PlanSummary& primarySummary(const RunSetup& setup) const {
    return setup.primaryKind() == VehicleKind::GroundRobot ? robots.summary : quadrotors.summary;
  }
};

// Plans every vehicle of the run; the quadrotors are planned even when the robots have none, so
// that bad input is found either way. Throws InputError for bad planner or trajectory
// parameters (and what planRobots and planQuadrotors throw for).
RunPlan planRun(const Scenario& scenario, const RunSetup& setup, const WorldModel& world,
                const RunRequest& request, const RunReporter& report);

// Each vehicle's plan, in the scenario's order: a quadrotor's as its planner made it; a robot's
// with its timed plan as path (corner points on the floor) and point_times (a navigator's as
// far as it went). Empty for vehicles not planned (planning stopped at an earlier failure).
std::vector<VehiclePlan> vehiclePlans(const Scenario& scenario, const RunSetup& setup,
                                      const RunPlan& plan);

}  // namespace cosim
