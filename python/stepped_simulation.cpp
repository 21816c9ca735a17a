#include "python/stepped_simulation.h"

#include <stdexcept>

#include "core/input_error.h"
#include "core/stop_request.h"
#include "run/metrics_json.h"
#include "run/run_evaluation.h"
#include "run/run_pipeline.h"
#include "run/scenario_checks.h"
#include "sim/flight_simulation.h"

namespace cosim::python {

SteppedSimulation::SteppedSimulation(const std::string& path,
                                     const std::vector<std::string>& overrides)
    : scenario_(loadCheckedScenario(path, overrides, PlannerUse::Run)) {
  // The stages of executeRun (run/run_pipeline.cpp) up to the simulation, and its options for a
  // flight (run/run_simulation.cpp).
  try {
    setup_ = resolveRun(scenario_, false);
    if (setup_.primaryKind() == VehicleKind::GroundRobot)
      throw InputError(scenario_.file, "key vehicles",
                       "cosim.Simulation steps quadrotor runs; this scenario has ground robots "
                       "(run it with cosim.run)");
    world_.emplace(WorldModel::build(scenario_));
    RunRequest request;
    request.interrupt = &stopRequestFlag();
    const RunReporter report(request.observer);
    plan_ = planRun(scenario_, setup_, *world_, request, report);
    pilots_ = buildPilots(scenario_, setup_, *world_, plan_);
  } catch (const InputError& e) {
    throw e.inFile(path);  // as `cosim run` reports a late error (a planner's grid too large)
  }
  if (!plan_.drivable()) throw std::runtime_error(plan_.message);
  for (const VehicleHandles& v : world_->vehicles()) names_.push_back(v.name);
  FlightOptions flight;
  flight.settings = scenario_.sim;
  loop_ = std::make_unique<SimulationLoop>(*world_, scenario_, no_robots_, pilots_.quadrotors,
                                           flightSimulationOptions(flight));
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
  return *pilots_.quadrotors.at(vehicle).believed_airframe;
}

void SteppedSimulation::setController(std::size_t vehicle, FlightController* controller) {
  pilots_.quadrotors.at(vehicle).controller =
      controller ? controller : pilots_.quadrotor_controllers.at(vehicle).get();
}

JsonObject SteppedSimulation::metricsJson() const {
  RunLog log = loop_ ? loop_->snapshot() : final_log_;
  const bool running = log.end_reason.empty();
  if (running) log.end_reason = "running";
  const RunMetrics metrics = evaluateRun(scenario_, setup_, *world_, plan_, log);
  JsonObject json = runMetricsJson({scenario_, setup_, *world_, plan_, metrics, log});
  if (running)
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
