#pragma once
// What Python's cosim.Simulation steps: the run's prepare stage (run/prepared_run.h, the very
// stages, stop checks and loop options `cosim run` takes), then its simulation loop
// (sim/simulation_loop.h) one control period at a time, and the run's own evaluation of the log
// at any moment (summarizeRun). Quadrotor runs only: ground robots drive under a navigator and
// path followers that only the whole pipeline runs.
#include <memory>
#include <string>
#include <vector>

#include "core/json_writer.h"
#include "run/prepared_run.h"
#include "sim/simulation_loop.h"

namespace cosim::python {

class SteppedSimulation {
 public:
  // Loads `path` with `overrides` (--set's "key=value"), prepares the run and starts the loop
  // with the vehicles hovering at their starts. Throws InputError for bad input and for a
  // scenario with ground robots, std::runtime_error if planning found no flyable plan (its
  // message: "no path found: ...") or was stopped. Preparing polls the stop request
  // (core/stop_request.h).
  SteppedSimulation(const std::string& path, const std::vector<std::string>& overrides);
  SteppedSimulation(const SteppedSimulation&) = delete;
  SteppedSimulation& operator=(const SteppedSimulation&) = delete;

  const std::vector<std::string>& vehicleNames() const { return names_; }
  double time() const { return loop_ ? loop_->time() : final_log_.sim_time; }
  double controlRate() const { return control_rate_; }
  // The run has ended (goal held, max_time, a fault), or close() ended it.
  bool done() const { return !loop_ || loop_->done(); }
  bool closed() const { return !loop_; }

  // One control period (false once the run has ended). Throws std::logic_error after close.
  bool stepControl();
  TrueVehicleState trueState(std::size_t vehicle) const;
  // What vehicle's flight software believes of its airframe (sim/model_error.h).
  const QuadrotorParams& believedAirframe(std::size_t vehicle) const;
  // Flies `vehicle` under `controller` from the next control step (nullptr: its built-in one,
  // where it left off). The caller keeps `controller` alive while it is in place.
  void setController(std::size_t vehicle, FlightController* controller);

  // metrics.json's object for the log so far. While the run goes on, end_reason is "running"
  // and the message says so (the pipeline's evaluation would call it a missed goal).
  JsonObject metricsJson() const;
  // Ends the run (an unfinished one as "interrupted", as SimulationLoop::finish) and frees
  // MuJoCo's data; the log stays for metricsJson. Idempotent.
  void close();

 private:
  const SimulationLoop& loop() const;

  const Scenario scenario_;
  PreparedRun run_;
  std::vector<std::string> names_;
  double control_rate_ = 0.0;
  // Last: it points into run_, and goes first.
  std::unique_ptr<SimulationLoop> loop_;
  RunLog final_log_;  // after close
};

}  // namespace cosim::python
