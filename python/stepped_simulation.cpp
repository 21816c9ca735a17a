#include "python/stepped_simulation.h"

#include <stdexcept>

#include "core/input_error.h"
#include "core/stop_request.h"
#include "run/metrics_json.h"
#include "run/run_simulation.h"
#include "run/scenario_checks.h"

namespace cosim::python {

namespace {

// The scenario as loaded, refused before any planning if it has ground robots.
Scenario quadrotorScenario(const std::string& path, const std::vector<std::string>& overrides) {
  Scenario s = loadCheckedScenario(path, overrides, PlannerUse::Run);
  if (resolveRun(s, false).primaryKind() == VehicleKind::GroundRobot)
    throw InputError(s.file, "key vehicles",
                     "cosim.Simulation steps quadrotor runs; this scenario has ground robots "
                     "(run it with cosim.run)");
  return s;
}

// Planning polls the stop request (Ctrl-C while the constructor plans); the loop does too, and
// no second thread: a Python controller runs on the caller's thread.
RunRequest steppedRequest() {
  RunRequest request;
  request.interrupt = &stopRequestFlag();
  return request;
}

}  // namespace

SteppedSimulation::SteppedSimulation(const std::string& path,
                                     const std::vector<std::string>& overrides)
    : scenario_(quadrotorScenario(path, overrides)), run_(prepareRun(scenario_, steppedRequest())) {
  if (run_.stopped) throw std::runtime_error("interrupted");
  if (!run_.plan.drivable()) throw std::runtime_error(run_.plan.message);
  for (const VehicleHandles& v : run_.world.vehicles()) names_.push_back(v.name);
  loop_ = startRunLoop(run_);
  control_rate_ = loop_->controlRate();
}

const SimulationLoop& SteppedSimulation::loop() const {
  if (!loop_) throw std::logic_error("the simulation is closed");
  return *loop_;
}

bool SteppedSimulation::stepControl() {
  loop();  // not closed
  return loop_->stepControl();
}

TrueVehicleState SteppedSimulation::trueState(std::size_t vehicle) const {
  return loop().vehicleState(vehicle);
}

const QuadrotorParams& SteppedSimulation::believedAirframe(std::size_t vehicle) const {
  // A quadrotor run: the world's vehicles are the quadrotors, in order.
  return *run_.pilots.quadrotors.at(vehicle).believed_airframe;
}

void SteppedSimulation::setController(std::size_t vehicle, FlightController* controller) {
  run_.pilots.quadrotors.at(vehicle).controller =
      controller ? controller : run_.pilots.quadrotor_controllers.at(vehicle).get();
}

JsonObject SteppedSimulation::metricsJson() const {
  const RunLog log = loop_ ? loop_->snapshot() : final_log_;
  JsonObject json = runMetricsJson(scenario_, summarizeRun(run_, log));
  if (log.end_reason == RunEnd::Running)
    json.add("message",
             "running: the simulation has not ended (t = " + std::to_string(log.sim_time) + " s)");
  return json;
}

void SteppedSimulation::close() {
  if (!loop_) return;
  final_log_ = loop_->finish();
  loop_.reset();
}

}  // namespace cosim::python
