#pragma once
// Where the simulation loop's time goes (sim/simulation_loop.h fills it when
// SimulationOptions::profile points at one): the engine, our own per-step work, and MuJoCo's own
// split of the engine's time. `cosim bench --section team_scale` prints it.
#include <mujoco/mujoco.h>
#include <time.h>

#include <algorithm>

namespace cosim {

struct LoopProfile {
  // Wall seconds, summed over the run.
  double wall = 0.0;         // the loop, from its first control step to its end
  double cpu = 0.0;          // CPU time of the loop's own thread over the same steps
  double engine = 0.0;       // mj_step (or mj_step1 and mj_step2), on the loop's thread
  double controllers = 0.0;  // every vehicle's estimator, reference, controller and log sample
  double forces = 0.0;       // rotors, air (sim/aerodynamics.h), drive servos
  double after_step = 0.0;   // contact bookkeeping, sensors, the health check
  double waited = 0.0;       // the loop's thread waiting for the second thread after mj_step1
  // Controllers at the control steps that write a log sample and at those that do not: the
  // logging's cost is what the former take beyond the latter (see logging()).
  double controllers_logged = 0.0;
  long logged_steps = 0, control_steps = 0, physics_steps = 0;
  // True: controllers and forces ran on a second thread while the engine computed positions and
  // velocities (mj_step1), so they add to the wall time only where they outlast it.
  bool overlapped = false;
  // MuJoCo's own timers (mjData::timer durations, ms), when mjcb_time was set during the run.
  double mujoco_ms[mjNTIMER] = {};

  // CPU seconds of the calling thread (CLOCK_THREAD_CPUTIME_ID): time the other processes of a
  // busy machine take does not count.
  static double threadCpu() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return t.tv_sec + 1e-9 * t.tv_nsec;
  }

  double logging() const {
    const long unlogged = control_steps - logged_steps;
    if (logged_steps == 0 || unlogged == 0) return 0.0;
    const double per_step = (controllers - controllers_logged) / unlogged;
    return std::max(0.0, controllers_logged - logged_steps * per_step);
  }
};

}  // namespace cosim
