#pragma once
// How a group of vehicles moves: its planner, trajectory and controller sections, as a run uses
// them. A scenario has two such groups of keys (the top-level planner, trajectory and controller,
// and the `aerial` ones that drive quadrotors over ground robots); a run reads each group into
// one MotionSections value and resolves its defaults there (run/record/run_setup.h), never in the
// loaded Scenario.
#include <optional>
#include <string>

#include "core/param_set.h"
#include "planning/team/separation_ellipsoid.h"
#include "sim/scenario.h"
#include "sim/trajectory_mode.h"

namespace cosim {

struct PlannerSection {
  std::string name;     // empty: the vehicles follow their given waypoints
  ParamSet params;      // everything under planner: except name, margin and separation
  double margin = 0.3;  // m, safety margin added to the vehicle radius
  // A quadrotor team's separation ellipsoid; absent: each model's own.
  std::optional<SeparationEllipsoid> separation;
};

struct TrajectorySection {
  TrajectoryMode mode = TrajectoryMode::Waypoints;
  ParamSet params;  // max_speed, switch_radius, ...
};

struct ControllerSection {
  std::string name = "cascade";
  bool drag_compensation = false;  // rotor drag in the flatness feed-forward
  ParamSet gains;
  CrazyflieThrustPath thrust_path;  // the crazyflie_* controllers' firmware build
};

struct MotionSections {
  PlannerSection planner;
  TrajectorySection trajectory;
  ControllerSection controller;
};

// The top-level planner, trajectory and controller sections, as the file has them.
MotionSections topLevelSections(const Scenario& scenario);
// The `aerial` sections, as the file has them.
MotionSections aerialSections(const Scenario& scenario);

}  // namespace cosim
