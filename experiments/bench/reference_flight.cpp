#include "experiments/bench/reference_flight.h"

#include <algorithm>
#include <cstdio>
#include <vector>

#include "experiments/bench/bare_replay.h"
#include "run/given_reference_flight.h"
#include "run/run_evaluation.h"
#include "sim/flight_metrics.h"
#include "sim/flight_simulation.h"

namespace cosim::bench {

namespace {

constexpr double kTarget = 0.8;

// One flight of the figure-eight for sim.max_time in the full loop, as `cosim run` flies it.
RunLog flyOnce(const Scenario& s, const WorldModel& world) {
  FlightOptions options;
  options.settings = s.sim;
  options.hold_after_arrival = 1e9;  // fly for exactly max_time
  return flyGivenReference(s, world, options);
}

// The median A-B-A ratio of `flights` flights of `s`, and the totals behind the figures.
struct FlightSet {
  double ratio = 0.0, loop_s = 0.0, bare_s = 0.0, sim_s = 0.0, rmse = 0.0;
  long steps = 0;
};

FlightSet measureFlights(const Scenario& s, int flights) {
  const WorldModel world = WorldModel::build(s);
  // Several flights (one in quick mode), each timed between two bare replays of it, A-B-A: on a
  // shared machine the speed of the whole machine drifts by tens of per cent within a second,
  // and the mean of the replays before and after cancels a drift that is steady over the
  // flight. The ratio is the median of the flights' ratios: one flight in a few meets a burst of
  // other work. Every flight of the scenario is the same flight (same seed, same result), so an
  // untimed first flight gives the log the first replay follows.
  FlightSet out;
  std::vector<double> ratios;
  RunLog log = flyOnce(s, world);
  for (int i = 0; i < flights; ++i) {
    // A fair bare side: the same compiled model (world.model(), so the same body, world and
    // opt.timestep), exactly log.physics_steps mj_step calls (the loop's count), on the same
    // motion (the logged thrusts, and the logged state put back at each control step), with only
    // the per-step wrench write any driver of the engine must make; both are timed over the
    // stepping alone (the loop's clock starts after its setup, bareReplaySeconds' after
    // mj_makeData).
    const double before = bareReplaySeconds(world, log, s.sim, true);
    log = flyOnce(s, world);
    const double after = bareReplaySeconds(world, log, s.sim, true);
    const double bare = 0.5 * (before + after);
    ratios.push_back(bare / log.wall_time);  // same steps: the ratio of the step rates
    out.loop_s += log.wall_time;
    out.bare_s += bare;
    out.sim_s += log.sim_time;
    out.steps += log.physics_steps;
    out.rmse = evaluateReferenceFlight(s, log).rmse_m;
  }
  std::sort(ratios.begin(), ratios.end());
  out.ratio = ratios[ratios.size() / 2];
  return out;
}

}  // namespace

Section measureReferenceFlight(bool quick, const std::string& controller) {
  std::vector<std::string> sets;
  if (!controller.empty()) sets.push_back("controller.name=" + controller);
  if (quick) sets.push_back("sim.max_time=2");
  const Scenario s = loadScenario(COSIM_SCENARIOS_DIR "/crazyflie_figure8.yaml", sets);
  const int flights = quick ? 1 : 15;
  const FlightSet own = measureFlights(s, flights);
  // The same flights with the other Crazyflie estimator: the firmware's Kalman estimator must
  // cost no more than the EKF (the same target against bare mj_step).
  const std::string other =
      s.estimator.kind == EstimatorKind::CrazyflieKalman ? "ekf" : "crazyflie_kalman";
  sets.push_back("estimator.name=" + other);
  const FlightSet alt =
      measureFlights(loadScenario(COSIM_SCENARIOS_DIR "/crazyflie_figure8.yaml", sets), flights);

  Section out;
  out.name = "reference_flight";
  out.figures = {{"bare_mj_step_steps_per_s", own.steps / own.bare_s, "1/s"},
                 {"full_loop_steps_per_s", own.steps / own.loop_s, "1/s"},
                 {"full_loop_sim_speed", own.sim_s / own.loop_s, "x real time"},
                 {"ratio_to_bare", own.ratio, "x"},
                 {"rmse_m", own.rmse, "m"},
                 {other + "_full_loop_steps_per_s", alt.steps / alt.loop_s, "1/s"},
                 {other + "_ratio_to_bare", alt.ratio, "x"},
                 {other + "_rmse_m", alt.rmse, "m"}};
  char target[32];
  std::snprintf(target, sizeof target, "%.2f", kTarget);
  const auto verdict = [&](double r) { return std::string(r >= kTarget ? "met" : "NOT met"); };
  out.note = s.vehicles[0].model + " flying the figure-eight reference under " +
             s.motion.controller.name + ", motion capture + IMU + " +
             estimatorName(s.estimator.kind) + " (then " + other + "), " +
             std::to_string(static_cast<int>(s.sim.control_rate)) + " Hz control; target " +
             "ratio >= " + target + ": " + verdict(own.ratio) + ", with " + other + ": " +
             verdict(alt.ratio);
  return out;
}

Section benchReferenceFlight(bool quick) {
  return measureReferenceFlight(quick, "");
}

}  // namespace cosim::bench
