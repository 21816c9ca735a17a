#pragma once
// What the state box at the top left of a frame says at time t: the time, each vehicle's speed
// and tracking error, and the planners. Readable however many vehicles there are: quadrotors
// are listed one per line, ground robots are summarised (how many are at their goals, the
// worst error and whose) when listing them all would crowd the box past its line budget.
#include <string>
#include <utility>
#include <vector>

#include "render/log_lookup.h"
#include "sim/vehicle_kind.h"

namespace cosim {

using StateLine = std::pair<std::string, std::string>;  // label, value

// One vehicle's entry in the box at time t (not the control state, VehicleState).
struct StateBoxVehicle {
  std::string name;
  VehicleKind kind = VehicleKind::Quadrotor;
  double speed = 0.0;  // m/s
  double error = 0.0;  // m, against `reference`
  ErrorReference reference = ErrorReference::Trajectory;
  bool at_goal = false;  // within the goal tolerance of its goal
};

// Robots beyond this many are summarised even when the box has room for them.
constexpr std::size_t kListedRobots = 4;

// The box's lines: "time", then the vehicles, then `planners` (label "planner" and, in a mixed
// run, "quadrotor planner"; then the controllers). max_lines: the most lines the frame has room
// for; a listing that would exceed it is summarised, and then the column heading dropped and the
// planners joined on one line ("planners": "cbs / theta_star", or "set-up" when controllers are
// among them); the time and the planners are always shown.
std::vector<StateLine> stateBoxLines(double t, const std::vector<StateBoxVehicle>& vehicles,
                                     const std::vector<StateLine>& planners, std::size_t max_lines);

}  // namespace cosim
