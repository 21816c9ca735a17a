#include "run/run_simulation.h"

#include <algorithm>
#include <cmath>
#include <thread>

#include "run/navigation_driver.h"
#include "run/prepared_run.h"
#include "sim/flight_simulation.h"

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
  log.end_reason = RunEnd::NoPath;
  return log;
}

SimulationOptions flightOptions(const Scenario& s, const RunRequest& request) {
  FlightOptions options;
  options.settings = s.sim;
  options.interrupt = request.interrupt;
  options.second_thread = secondThread(request);
  options.profile = request.profile;
  return flightSimulationOptions(options);
}

// Before each control step: progress in simulated seconds against the plan's makespan (the run
// ends about then), then the navigator's next decision, if a navigator drives.
SimulationOptions groundOptions(const Scenario& s, RobotPlans& plans, const RunRequest& request,
                                const RunReporter& report) {
  SimulationOptions options;
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

// What the navigator made of the drive: the robot's executed cells and its counters.
void recordNavigation(PreparedRun& run, RunLog& log) {
  RobotPlans& plans = run.plan.robots;
  if (!plans.navigator) return;
  log.vehicles[run.setup.robots.front()].planned_path = plans.navigator->executed();
  plans.summary.counters = plans.navigator->counters();
  plans.plans.front().counters = plans.summary.counters;
}

}  // namespace

SimulationOptions runLoopOptions(PreparedRun& run) {
  if (run.setup.primaryKind() == VehicleKind::GroundRobot)
    return groundOptions(run.scenario, run.plan.robots, run.request, run.report);
  return flightOptions(run.scenario, run.request);
}

std::unique_ptr<SimulationLoop> startRunLoop(PreparedRun& run) {
  run.report.stage(RunStage::Simulate);
  const RunSetup& setup = run.setup;
  if (setup.primaryKind() == VehicleKind::GroundRobot)
    run.report.message(
        "driving " + std::to_string(setup.robots.size()) + " ground robot(s)" +
        (setup.quadrotors.empty()
             ? std::string()
             : " under " + std::to_string(setup.quadrotors.size()) + " quadrotor(s)"));
  else
    run.report.message("flying (physics step " + std::to_string(run.scenario.sim.timestep) + " s)");
  return std::make_unique<SimulationLoop>(run.world, run.scenario, run.pilots.robots,
                                          run.pilots.quadrotors, run.loop);
}

RunLog flyRun(PreparedRun& run) {
  if (!run.plan.drivable()) {
    run.report.stage(RunStage::Simulate);
    return unplannedLog(run.scenario);
  }
  if (run.verified_flight) {  // the loop is deterministic: the same flight again
    run.report.stage(RunStage::Simulate);
    run.report.message("flown: the team's last verification flight is the run's");
    RunLog log = std::move(*run.verified_flight);
    run.verified_flight.reset();
    return log;
  }
  const std::unique_ptr<SimulationLoop> loop = startRunLoop(run);
  while (loop->stepControl()) {
  }
  RunLog log = loop->finish();
  recordNavigation(run, log);
  return log;
}

}  // namespace cosim
