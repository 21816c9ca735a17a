#pragma once
// Flight controllers by name (the names a scenario's `controller.name` takes), as the planner
// registry (planning/planner_registry.h) holds the planners: one entry per controller, registered
// from the controller's own file by a register<Name>Controller function listed in
// controller_registry.cpp. Everything that depends on which controller it is asks here: the
// scenario loader's name check and drag rule, makeFlightController, the team's tracking margin
// (run/team_tracking_margin.h) and `cosim run --list-controllers`.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "control/controller_gains.h"
#include "control/crazyflie_thrust_path.h"
#include "control/flight_controller.h"
#include "control/quadrotor_params.h"
#include "core/param_set.h"

namespace cosim {

// What a scenario sets beside the gains.
struct ControllerOptions {
  bool drag_compensation = false;   // controller.drag_compensation (entries that compensate drag)
  CrazyflieThrustPath thrust_path;  // the firmware build (entries on the Crazyflie thrust path)
};

// Builds the controller for an airframe, reading its gains from `gains` (names no declaration
// reads are left for the caller's requireAllUsed).
using ControllerFactory = std::function<std::unique_ptr<FlightController>(
    const QuadrotorParams& params, ParamSet& gains, const ControllerOptions& options)>;

struct ControllerEntry {
  std::string name;
  std::string summary;  // one line: the law and its source
  ControllerFactory make;
  std::vector<GainDeclaration> gains;
  // Ellipsoids: how much closer than planned a pair of vehicles flying this controller came
  // (run/team_tracking_margin.h): the flown closest approach of a pair planned 1.5 ellipsoids
  // apart was 1.5 minus this, the worse of experiments/scenarios/swarm32.yaml and
  // swarm32_dense.yaml (min_uav_separation_m, downwash on, default gains).
  double team_shortfall = 0.0;
  // Takes controller.drag_compensation: the rotor drag of Faessler et al. 2018 in the
  // feed-forward.
  bool compensates_drag = false;
  // A Crazyflie firmware law: takes the firmware build's thrust path (controller.thrust_map,
  // thrust_map_coefficients, idle_thrust, platform; control/crazyflie_thrust_path.h).
  bool crazyflie_thrust_path = false;
};

class ControllerRegistry {
 public:
  static const ControllerRegistry& instance();
  void add(ControllerEntry entry) { entries_.push_back(std::move(entry)); }
  const ControllerEntry* find(const std::string& name) const;
  // In the order of `cosim run --list-controllers`.
  const std::vector<ControllerEntry>& entries() const { return entries_; }

 private:
  std::vector<ControllerEntry> entries_;
};

// "" for a registered controller; else the problem with `name`, for key controller.name:
// "must be 'cascade', ... or 'crazyflie_pid'", with a did-you-mean where one is near.
std::string controllerNameProblem(const std::string& name);

// Whether `name` is registered and takes controller.drag_compensation.
bool compensatesDrag(const std::string& name);
// The controllers that do, for messages: "'geometric' and 'indi'".
std::string dragCompensatingControllers();

// Whether `name` is registered and takes the Crazyflie firmware build's thrust path.
bool takesCrazyflieThrustPath(const std::string& name);

}  // namespace cosim
