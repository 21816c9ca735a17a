#include "run/given_reference_flight.h"

#include <memory>
#include <vector>

#include "control/controller_factory.h"
#include "control/piecewise_polynomial_reference.h"
#include "run/record/run_setup.h"
#include "sim/model_error.h"

namespace cosim {

RunLog flyReference(const Scenario& scenario, const WorldModel& world,
                    const ControllerSection& section, const ReferenceFlight& flight,
                    const FlightOptions& options) {
  const QuadrotorParams believed =
      believedAirframe(world.vehicles()[0].params, scenario.model_error);
  ParamSet gains = section.gains;
  const std::unique_ptr<FlightController> controller = makeFlightController(
      section.name, gains, believed, section.drag_compensation, section.thrust_path);
  std::vector<VehiclePilot> pilots(1);
  pilots[0].controller = controller.get();
  pilots[0].reference = flight.reference;
  pilots[0].goal = flight.goal;
  pilots[0].believed_airframe = &believed;
  pilots[0].reference_end = flight.reference_end;
  return simulateFlight(world, scenario, pilots, options);
}

RunLog flyGivenReference(const Scenario& scenario, const WorldModel& world,
                         const FlightOptions& options) {
  const VehicleSpec& vehicle = scenario.vehicles.at(0);
  const RunSetup setup = resolveRun(scenario, false);
  PiecewisePolynomialReference reference = *vehicle.reference;
  return flyReference(scenario, world, setup.sectionsOf(0).controller,
                      {&reference, vehicle.goal(), reference.duration()}, options);
}

}  // namespace cosim
