#pragma once
// The simulation loop, stepped from outside one control period at a time. Each control period:
// every vehicle's controller at the control rate (a ground robot's through
// sim/ground_pilot_step.h, a quadrotor's through sim/aerial_pilot_step.h, in the world's order),
// a log sample at most log_rate times a second, then the control period's physics steps
// (sim/physics_stepper.h: rotors, air, mj_step, contacts, sensors), with the moving obstacles
// (mocap bodies) placed before every one. Every vehicle is logged at the same instants, so that
// sample k of every vehicle is at the same time. sim/flight_simulation.h and
// sim/ground_simulation.h run it to the end; a front end (Python) can step it, read the state
// and swap controllers between steps.
#include <mujoco/mujoco.h>

#include <Eigen/Core>
#include <atomic>
#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "sim/aerial_pilot_step.h"
#include "sim/ground_pilot_step.h"
#include "sim/loop_profile.h"
#include "sim/physics_stepper.h"
#include "sim/run_log.h"
#include "sim/scenario.h"
#include "sim/step_worker.h"
#include "sim/world_model.h"

namespace cosim {

struct SimulationOptions {
  SimSettings settings;
  double hold_after_arrival = 0.5;         // s a ground robot holds its goal before it is done
  double aerial_hold_after_arrival = 1.0;  // s a quadrotor hovers at its goal before it is done
  // A quadrotor whose mixer stays saturated this long without a break cannot follow its
  // reference (absurd gains, too heavy, a reference beyond the airframe): the run ends
  // "saturated".
  double max_saturated_time = 2.0;  // s
  // Log samples per second at most (ground robots move slowly: keeps logs small); 0: a sample at
  // every control step.
  double log_rate = 50.0;                        // Hz
  const std::atomic<bool>* interrupt = nullptr;  // set by SIGINT/SIGTERM handlers
  // Called at each control step before the controllers, with the robots' measured states; a
  // navigator extends the pilots' paths here. Returning false ends the run as
  // RunEnd::GaveUp.
  std::function<bool(double t, const std::vector<PlanarState>& states)> before_control;
  // Centre (x, y) of moving obstacle i at time t; default: the scenario's path and speed.
  std::function<Eigen::Vector2d(std::size_t i, double t)> obstacle_position;
  // Run the vehicles' controllers and the step's forces on a second thread while MuJoCo computes
  // the step's positions and velocities (mj_step1; then mj_step2): the same numbers as one
  // thread, in the time of the engine alone where the second thread has a core. Ignored where
  // the forces read MuJoCo's geometry (ground effect) or the integrator is RK4. The controllers
  // then run off the caller's thread: leave it off for controllers that must run on it (Python).
  bool second_thread = false;
  LoopProfile* profile = nullptr;  // filled as the loop runs (sim/loop_profile.h), if given
};

// A vehicle's true state, read from mjData (not what its controller estimates). The free joint's
// qpos and qvel as they are; a planar base (slide x, slide y, hinge yaw) at its fixed height,
// level, turned by its yaw.
struct TrueVehicleState {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();          // world, m
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();          // world, m/s
  Eigen::Vector4d quaternion = Eigen::Vector4d::UnitX();       // w, x, y, z; body to world
  Eigen::Vector3d angular_velocity = Eigen::Vector3d::Zero();  // body frame, rad/s
};

class SimulationLoop {
 public:
  // `robots` are the world's ground robots in order, `quadrotors` its other vehicles in order
  // (the log keeps the world's order); throws std::invalid_argument unless there is one pilot
  // per vehicle. world, scenario and both pilot vectors must outlive the loop, and the vectors
  // must not be resized while it runs: the loop holds pointers to their elements. Between two
  // stepControl calls a caller may point a quadrotor's VehiclePilot::controller (or reference)
  // at another one: the next control step uses it as it is (the loop resets only the
  // controllers it begins with; reset a new one first if it keeps state). believed_airframe is
  // read once, here. The wall clock of the log starts here.
  SimulationLoop(const WorldModel& world, const Scenario& scenario,
                 std::vector<GroundPilot>& robots, std::vector<VehiclePilot>& quadrotors,
                 const SimulationOptions& options);
  ~SimulationLoop();
  SimulationLoop(const SimulationLoop&) = delete;
  SimulationLoop& operator=(const SimulationLoop&) = delete;

  // One control period: the controllers at time(), then up to stepsPerControl physics steps.
  // Returns false once the run has ended: every vehicle reached its goal and held it (Goal),
  // max_time, an interrupt, a fault (Diverged: a NaN state or a quadrotor far outside the
  // world; Unstable: MuJoCo found bad numbers; Saturated: a quadrotor's mixer), or
  // before_control giving up. Does nothing once the run has ended.
  bool stepControl();
  bool done() const { return done_; }
  double time() const;                                          // s of simulated time
  RunEnd endReason() const { return end_reason_; }  // Running until the run ends
  // The run's log, with the wall time, simulated time and physics steps. Callable once; frees
  // the mjData. A run that has not ended ends Interrupted.
  RunLog finish();
  // The log so far, as finish() would return it at this moment (end_reason: endReason(), Running
  // while the run goes on), without ending the run: for a front end's metrics mid-flight. A copy
  // of every sample. Throws std::logic_error after finish.
  RunLog snapshot() const;

  const mjData* data() const { return d_.get(); }      // nullptr after finish
  TrueVehicleState vehicleState(std::size_t v) const;  // v: the vehicle's index in the world
  double controlRate() const { return 1.0 / physics_.controlDt(); }  // Hz, as stepped

 private:
  struct DataDeleter {
    void operator()(mjData* d) const { mj_deleteData(d); }
  };
  void beginVehicles(const Scenario& scenario, std::vector<GroundPilot>& robots,
                     std::vector<VehiclePilot>& quadrotors);
  void placeObstacles(double t);
  // The control step: every vehicle's controller and the log; how the run ends, or none.
  // prepare (the interrupt, the robots' states, before_control) runs on the loop's thread,
  // controlVehicles on the second thread when there is one.
  std::optional<RunEnd> control();
  std::optional<RunEnd> prepare();
  std::optional<RunEnd> controlVehicles(const mjData* d);
  std::optional<RunEnd> physicsStep();     // one physics step on one thread; a fault, or none
  std::optional<RunEnd> overlappedStep();  // the same with the second thread; control first
  void secondThreadJob();        // the second thread's share of overlappedStep
  bool end(RunEnd reason);

  const WorldModel& world_;
  SimulationOptions options_;
  // Which pilot drives vehicle v: robots[pilot_[v]] or quadrotors[pilot_[v]].
  std::vector<std::size_t> pilot_;
  std::unique_ptr<mjData, DataDeleter> d_;
  PhysicsStepper physics_;
  int controls_per_log_ = 1;
  std::vector<int> mocap_;  // moving obstacle i's mocap index (-1: not in the model)
  std::vector<GroundPilotStep> drives_;
  std::vector<AerialPilotStep> flights_;
  std::vector<PlanarState> states_;  // the robots' states at the control step
  RunLog log_;
  std::unique_ptr<StepWorker> worker_;  // the second thread (SimulationOptions::second_thread)
  // What the second thread reads: d_'s arrays, but qpos as it was before mj_step1 (a copy), and
  // d_'s time. Not for MuJoCo's functions (its stack is d_'s).
  mjData view_{};
  std::vector<mjtNum> qpos_seen_;
  bool control_due_ = false;            // the next overlapped step starts with the control step
  std::optional<RunEnd> control_reason_;  // what the second thread's control step ended with
  long control_count_ = 0;
  bool done_ = false;
  RunEnd end_reason_ = RunEnd::Running;
  double end_time_ = 0.0;  // time() after finish
};

}  // namespace cosim
