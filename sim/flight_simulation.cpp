#include "sim/flight_simulation.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "sim/contact_monitor.h"
#include "sim/disturbances.h"
#include "sim/simulation_health.h"

namespace cosim {

RunLog simulateFlight(const WorldModel& world, const Scenario& scenario,
                      std::vector<VehiclePilot>& pilots, const FlightOptions& options) {
  const mjModel* m = world.model();
  mjData* d = mj_makeData(m);
  mj_resetData(m, d);
  // Vehicles start hovering.
  for (const VehicleHandles& v : world.vehicles()) startHovering(m, d, v);
  mj_forward(m, d);

  const SimSettings& cfg = options.settings;
  const int steps_per_control =
      std::max(1, static_cast<int>(std::lround(1.0 / (cfg.timestep * cfg.control_rate))));
  const double control_dt = steps_per_control * m->opt.timestep;
  const long max_steps = static_cast<long>(std::ceil(cfg.max_time / m->opt.timestep));
  const auto& vehicles = world.vehicles();

  const AerialStepRules rules(cfg, scenario.world, options.hold_after_arrival,
                              options.max_saturated_time);

  RunLog log;
  std::vector<AerialPilotStep> steps;
  for (std::size_t v = 0; v < vehicles.size(); ++v) {
    steps.emplace_back(vehicles[v], pilots[v], rules);
    log.vehicles.push_back(
        steps.back().begin(static_cast<std::size_t>(cfg.max_time / control_dt) + 2));
  }
  ContactMonitor contacts(m, world, scenario);
  Disturbances disturbances(scenario.disturbances, world, scenario.world.bounds_min.z(),
                            scenario.sim.seed);
  const bool disturbed = scenario.disturbances.any();

  const auto wall_start = std::chrono::steady_clock::now();
  long step = 0;
  log.end_reason = "max_time";
  for (; step < max_steps; ++step) {
    if (step % steps_per_control == 0) {
      if (options.interrupt && options.interrupt->load()) {
        log.end_reason = "interrupted";
        break;
      }
      bool all_done = true;
      for (std::size_t v = 0; v < vehicles.size(); ++v) {
        const AerialPilotStep::Outcome o = steps[v].step(m, d, control_dt, log.vehicles[v], true);
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
    if (disturbed) disturbances.apply(m, d, m->opt.timestep);
    mj_step(m, d);
    contacts.update(d, log);
    if (const char* fault = physicsFault(m, d)) {
      log.end_reason = fault;
      ++step;
      break;
    }
  }
  log.wall_time =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  log.sim_time = d->time;
  log.physics_steps = step;
  for (int i = 0; i < mjNWARNING; ++i) log.mujoco_warnings += d->warning[i].number;
  mj_deleteData(d);
  return log;
}

}  // namespace cosim
