#pragma once
// The physics half of the simulation loop (sim/simulation_loop.h): how many physics steps a
// control period and the time limit are, the quadrotors' rotors and sensors
// (sim/quadrotor_plant.h), one physics step with what must surround it (the rotors advance, the
// air acts on the quadrotors, mj_step, contact bookkeeping, the sensors sample, the check that
// the state can still be trusted), and the figures a finished run's log records.
#include <mujoco/mujoco.h>

#include <array>
#include <chrono>
#include <memory>
#include <vector>

#include "sim/aerodynamics.h"
#include "sim/contact_monitor.h"
#include "sim/quadrotor_plant.h"
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

  // Vehicle v's rotors and sensors (v a quadrotor of the world).
  QuadrotorPlant& plant(std::size_t v) { return *plants_[v]; }
  // Ground robot v's drive servos (sim/urdf_vehicle.h, GroundDrive::servos): the speed each is
  // commanded (held until the next command; clamped to the servo's range) and the force it
  // applied in the last physics step.
  void commandDrive(std::size_t v, int servo, double speed);
  double driveCommand(std::size_t v, int servo) const { return drive_command_[v][servo]; }
  double driveForce(std::size_t v, int servo) const { return drive_force_[v][servo]; }
  // Every quadrotor's rotors spinning at hover speed (its true weight shared by four): the
  // vehicles start hovering rather than dropping for the rotors' lag.
  void startHovering(mjData* d);

  // Starts the wall clock of the loop (call just before it).
  void startClock() { wall_start_ = std::chrono::steady_clock::now(); }
  // One physics step. Returns how the run ends if the state can no longer be trusted
  // (Diverged, Unstable; see sim/simulation_health.h), else none.
  std::optional<RunEnd> step(mjData* d, RunLog& log);
  // The same step in parts, for a loop that times them or overlaps them (sim/simulation_loop.h):
  // applyForces, then the engine (mj_step, or mj_step1 then mj_step2), then afterStep.
  // applyForces advances the rotors and writes the step's applied forces (rotors, air, drive
  // servos) from qpos, qvel and the rotors only, so it may run while mj_step1 computes positions
  // and velocities on another thread, unless forcesReadGeometry(). afterStep books contacts,
  // samples the sensors and checks the state (step's return value).
  void applyForces(mjData* d);
  std::optional<RunEnd> afterStep(mjData* d, RunLog& log);
  // The forces read positions MuJoCo computes (ground effect casts rays against the geoms).
  bool forcesReadGeometry() const { return ground_effect_; }
  // Records in `log` the loop's wall time, the simulated time, the steps taken and MuJoCo's
  // warning count.
  void finish(const mjData* d, RunLog& log) const;

 private:
  const mjModel* m_;
  const WorldModel& world_;
  int steps_per_control_;
  double control_dt_;
  long max_steps_;
  ContactMonitor contacts_;
  Aerodynamics aerodynamics_;
  std::vector<std::unique_ptr<QuadrotorPlant>> plants_;  // nullptr for ground robots
  std::vector<QuadrotorPlant*> plant_pointers_;          // the same, as Aerodynamics wants them
  bool sensing_;                                         // any sensor to sample
  bool ground_effect_;
  std::vector<std::array<double, 3>> drive_command_, drive_force_;  // per vehicle, per servo
  std::chrono::steady_clock::time_point wall_start_ = std::chrono::steady_clock::now();
  long steps_ = 0;
};

}  // namespace cosim
