#include "run/given_reference_flight.h"

#include <memory>
#include <vector>

#include "control/controller_factory.h"
#include "control/piecewise_polynomial_reference.h"
#include "sim/model_error.h"

namespace cosim {

RunLog flyGivenReference(const Scenario& scenario, const WorldModel& world,
                         const FlightOptions& options) {
  const VehicleSpec& vehicle = scenario.vehicles.at(0);
  const QuadrotorParams believed =
      believedAirframe(world.vehicles()[0].params, scenario.model_error);
  ParamSet gains = scenario.motion.controller.gains;
  const std::unique_ptr<FlightController> controller = makeFlightController(
      scenario.motion.controller.name, gains, believed,
      scenario.motion.controller.drag_compensation, scenario.motion.controller.thrust_path);
  PiecewisePolynomialReference reference = *vehicle.reference;
  std::vector<VehiclePilot> pilots(1);
  pilots[0].controller = controller.get();
  pilots[0].reference = &reference;
  pilots[0].goal = vehicle.goal();
  pilots[0].believed_airframe = &believed;
  pilots[0].reference_end = reference.duration();
  return simulateFlight(world, scenario, pilots, options);
}

}  // namespace cosim
