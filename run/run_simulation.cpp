#include "run/run_simulation.h"

#include <algorithm>
#include <cmath>
#include <thread>

#include "run/navigation_driver.h"
#include "run/run_end.h"
#include "run/run_pipeline.h"
#include "sim/flight_simulation.h"
#include "sim/ground_simulation.h"

namespace cosim {

namespace {

bool secondThread(const RunRequest& request) {
  return request.loop_threads >= 2 && std::thread::hardware_concurrency() >= 2;
}

// The log of a run whose vehicles had no plan to follow: who they were, where they were going.
RunLog unplannedLog(const Scenario& s) {
  RunLog log;
  for (const VehicleSpec& v : s.vehicles) {
    VehicleLog& vl = log.vehicles.emplace_back();
    vl.name = v.name;
    vl.goal = v.goal();
  }
  log.end_reason = kNoPathEndReason;
  return log;
}

RunLog fly(const Scenario& s, const WorldModel& world, RunPilots& pilots, const RunRequest& request,
           const RunReporter& report) {
  report.message("flying (physics step " + std::to_string(s.sim.timestep) + " s)");
  FlightOptions options;
  options.settings = s.sim;
  options.interrupt = request.interrupt;
  options.second_thread = secondThread(request);
  options.profile = request.profile;
  return simulateFlight(world, s, pilots.quadrotors, options);
}

// Before each control step: progress in simulated seconds against the plan's makespan (the run
// ends about then), then the navigator's next decision, if a navigator drives.
GroundSimOptions groundOptions(const Scenario& s, RobotPlans& plans, const RunRequest& request,
                               const RunReporter& report) {
  GroundSimOptions options;
  options.settings = s.sim;
  options.interrupt = request.interrupt;
  options.second_thread = secondThread(request);
  options.profile = request.profile;
  NavigationDriver* driver = plans.navigator.get();
  if (driver)
    options.obstacle_position = [driver](std::size_t i, double t) {
      return driver->obstacle(i, t);
    };
  double planned_end = 0.0;
  for (const auto& path : plans.paths) planned_end = std::max(planned_end, path.endTime());
  const int total = static_cast<int>(std::ceil(planned_end));
  options.before_control = [driver, total, &report, shown = -1](
                               double t, const std::vector<PlanarState>&) mutable {
    if (static_cast<int>(t) != shown) {
      shown = static_cast<int>(t);
      report.progress("driving (simulated s)", shown, total);
    }
    return driver ? driver->update(t) : true;
  };
  return options;
}

RunLog drive(const Scenario& s, const RunSetup& setup, const WorldModel& world, RobotPlans& plans,
             RunPilots& pilots, const RunRequest& request, const RunReporter& report) {
  const GroundSimOptions options = groundOptions(s, plans, request, report);
  report.message("driving " + std::to_string(pilots.robots.size()) + " ground robot(s)" +
                 (setup.quadrotors.empty()
                      ? std::string()
                      : " under " + std::to_string(setup.quadrotors.size()) + " quadrotor(s)"));
  RunLog log = simulateGround(world, s, pilots.robots, pilots.quadrotors, options);
  if (plans.navigator) {
    log.vehicles[setup.robots.front()].planned_path = plans.navigator->executed();
    plans.summary.counters = plans.navigator->counters();
    plans.plans.front().counters = plans.summary.counters;
  }
  return log;
}

}  // namespace

RunLog simulateRun(const Scenario& scenario, const RunSetup& setup, const WorldModel& world,
                   RunPlan& plan, RunPilots& pilots, const RunRequest& request,
                   const RunReporter& report) {
  if (!plan.drivable()) return unplannedLog(scenario);
  if (setup.primaryKind() == VehicleKind::GroundRobot)
    return drive(scenario, setup, world, plan.robots, pilots, request, report);
  return fly(scenario, world, pilots, request, report);
}

}  // namespace cosim
