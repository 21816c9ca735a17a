#pragma once
// The physics half that both simulation loops (sim/flight_simulation, sim/ground_simulation)
// share: how many physics steps a control period and the time limit are, one physics step with
// what must surround it (disturbances on the quadrotors, mj_step, contact bookkeeping, the check
// that the state can still be trusted), and the figures a finished run's log records.
#include <mujoco/mujoco.h>

#include <chrono>

#include "sim/contact_monitor.h"
#include "sim/disturbances.h"
#include "sim/run_log.h"
#include "sim/scenario.h"
#include "sim/world_model.h"

namespace cosim {

class PhysicsStepper {
 public:
  PhysicsStepper(const WorldModel& world, const Scenario& scenario, const SimSettings& settings);

  int stepsPerControl() const { return steps_per_control_; }
  double controlDt() const { return control_dt_; }  // s, a whole number of physics steps
  long maxSteps() const { return max_steps_; }      // settings.max_time in physics steps
  long stepsTaken() const { return steps_; }

  // Starts the wall clock of the loop (call just before it).
  void startClock() { wall_start_ = std::chrono::steady_clock::now(); }
  // One physics step. Returns the run's end_reason if the state can no longer be trusted
  // ("diverged", "unstable"; see sim/simulation_health.h), else nullptr.
  const char* step(mjData* d, RunLog& log);
  // Records in `log` the loop's wall time, the simulated time, the steps taken and MuJoCo's
  // warning count.
  void finish(const mjData* d, RunLog& log) const;

 private:
  const mjModel* m_;
  int steps_per_control_;
  double control_dt_;
  long max_steps_;
  ContactMonitor contacts_;
  Disturbances disturbances_;
  bool disturbed_;
  std::chrono::steady_clock::time_point wall_start_ = std::chrono::steady_clock::now();
  long steps_ = 0;
};

}  // namespace cosim
