#include "sim/flight_simulation.h"

#include <algorithm>
#include <cmath>

#include "sim/physics_stepper.h"

namespace cosim {

RunLog simulateFlight(const WorldModel& world, const Scenario& scenario,
                      std::vector<VehiclePilot>& pilots, const FlightOptions& options) {
  const mjModel* m = world.model();
  mjData* d = mj_makeData(m);
  mj_resetData(m, d);
  const SimSettings& cfg = options.settings;
  PhysicsStepper physics(world, scenario, cfg);
  physics.startHovering(d);  // vehicles start hovering
  mj_forward(m, d);
  const double control_dt = physics.controlDt();
  const auto& vehicles = world.vehicles();

  const AerialStepRules rules(cfg, scenario.world, options.hold_after_arrival,
                              options.max_saturated_time);
  const AerialSensing sensing{scenario.sensors, scenario.estimator, cfg.seed};

  RunLog log;
  std::vector<AerialPilotStep> steps;
  for (std::size_t v = 0; v < vehicles.size(); ++v) {
    steps.emplace_back(vehicles[v], pilots[v], rules, sensing, v);
    log.vehicles.push_back(
        steps.back().begin(d, static_cast<std::size_t>(cfg.max_time / control_dt) + 2));
  }

  physics.startClock();
  log.end_reason = "max_time";
  for (long step = 0; step < physics.maxSteps(); ++step) {
    if (step % physics.stepsPerControl() == 0) {
      if (options.interrupt && options.interrupt->load()) {
        log.end_reason = "interrupted";
        break;
      }
      bool all_done = true;
      for (std::size_t v = 0; v < vehicles.size(); ++v) {
        const AerialPilotStep::Outcome o =
            steps[v].step(d, physics.plant(v), control_dt, log.vehicles[v], true);
        if (o.saturated) log.end_reason = "saturated";
        all_done = all_done && o.done;
        if (o.diverged) log.end_reason = "diverged";
      }
      if (log.end_reason == "diverged" || log.end_reason == "saturated") break;
      if (all_done) {
        log.end_reason = "goal";
        break;
      }
    }
    if (const char* fault = physics.step(d, log)) {
      log.end_reason = fault;
      break;
    }
  }
  physics.finish(d, log);
  mj_deleteData(d);
  return log;
}

}  // namespace cosim
