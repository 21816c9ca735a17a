#include "run/run_plan.h"

#include "run/run_pipeline.h"

namespace cosim {

RunPlan planRun(const Scenario& scenario, const RunSetup& setup, const WorldModel& world,
                const RunRequest& request, const RunReporter& report) {
  RunPlan plan;
  if (setup.primaryKind() == VehicleKind::GroundRobot)
    plan.robots = planRobots(scenario, setup, world, request.given_team_plan);
  if (!setup.quadrotors.empty())
    plan.quadrotors = planQuadrotors(scenario, setup.quadrotor_sections, world, setup.quadrotors,
                                     setup.quadrotor_planning, request, report);
  if (!drivable(plan.robots.status)) {
    plan.status = plan.robots.status;
    plan.message = plan.robots.message;
  } else if (plan.quadrotors.status != PlanStatus::Ready) {
    plan.status = plan.quadrotors.status;
    plan.message = plan.quadrotors.failure;
  } else {
    plan.status = plan.robots.status;  // Ready, or Conflicting: driven anyway
    plan.message = plan.robots.message;
  }
  return plan;
}

std::vector<VehiclePlan> vehiclePlans(const Scenario& scenario, const RunSetup& setup,
                                      const RunPlan& plan) {
  std::vector<VehiclePlan> plans(scenario.vehicles.size());
  for (std::size_t k = 0; k < setup.quadrotors.size() && k < plan.quadrotors.plans.size(); ++k)
    plans[setup.quadrotors[k]] = plan.quadrotors.plans[k];
  const RobotPlans& robots = plan.robots;
  for (std::size_t k = 0; k < setup.robots.size() && k < robots.plans.size(); ++k) {
    VehiclePlan& p = plans[setup.robots[k]];
    p = robots.plans[k];
    if (k >= robots.paths.size()) continue;
    p.path.waypoints.clear();
    for (const auto& point : robots.paths[k].points())
      p.path.waypoints.push_back(floorPoint(point));
    p.point_times = robots.paths[k].times();
  }
  return plans;
}

}  // namespace cosim
