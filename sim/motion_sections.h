#pragma once
// How a group of vehicles moves: its planner, trajectory and controller sections. A scenario has
// two such groups (Scenario::motion, the top-level planner, trajectory and controller, and
// Scenario::aerial, the `aerial` ones that drive quadrotors over ground robots), read by one
// reader from the keys declared here once (sim/scenario_motion.cpp). A run resolves their
// defaults in its own copy (run/run_setup.h), never in the loaded Scenario. Planner parameters,
// trajectory parameters and controller gains are free-form ParamSets the planners, the flight
// and the controllers check themselves.
#include <optional>
#include <string>
#include <vector>

#include "control/cascade_controller.h"
#include "control/crazyflie_thrust_path.h"
#include "core/param_set.h"
#include "planning/team/separation_ellipsoid.h"
#include "sim/declared_keys.h"
#include "sim/trajectory_mode.h"

namespace cosim {

struct PlannerSection {
  std::string name;     // empty: the vehicles follow their given waypoints
  ParamSet params;      // everything under planner: except the keys declared below
  double margin = 0.3;  // m, safety margin added to the vehicle radius
  // A quadrotor team's separation ellipsoid; absent: each model's own.
  std::optional<SeparationEllipsoid> separation;
  // The name was chosen by an override (--planner, --set planner.name, a sweep's vary, Python's
  // planner=) rather than by the file; the parameters that overrides set. A file's parameters
  // of another planner are then set aside (run/scenario_planning.h, plannerParameters).
  bool name_from_override = false;
  std::vector<std::string> params_from_overrides;

  // The keys (sim/declared_keys.h); every other key is one of the planner's parameters.
  template <class Visitor>
  void declareKeys(Visitor& v) {
    v.text("name", name,
           "the planner (docs/planners.md), required in the section; without the section the "
           "vehicles fly their given waypoints");
    v.number("margin", margin, 0.0, 100.0, "m, safety margin added to the vehicle's radius");
    v.custom("separation", "{radius, height}",
             "m, the ellipsoid a quadrotor team keeps apart, each in [0.001, 100]; absent: each "
             "model's own");
  }
};

struct TrajectorySection {
  TrajectoryMode mode = TrajectoryMode::Waypoints;
  ParamSet params;  // max_speed, switch_radius, ...: checked by the flight for the mode

  template <class Visitor>
  void declareKeys(Visitor& v) {
    v.choice(
        "mode", mode, kTrajectoryModeNames,
        "waypoint switching (Navratil 2019) or a minimum-snap polynomial; every other key is a "
        "parameter of the mode");
  }
};

struct ControllerSection {
  std::string name = CascadeController::kName;  // a name of control/controller_registry.h
  // A controller section was written; without one a quadrotor team flies indi (run_setup.cpp).
  bool given = false;
  bool drag_compensation = false;  // rotor drag in the flatness feed-forward (geometric, indi)
  ParamSet gains;
  CrazyflieThrustPath thrust_path;  // the crazyflie_* controllers' firmware build

  // The keys (sim/declared_keys.h); the thrust path's are read by readCrazyflieThrustPath
  // (sim/scenario_power.cpp).
  template <class Visitor>
  void declareKeys(Visitor& v) {
    v.text("name", name,
           "`cascade`, `geometric`, `indi`, `dsl_pid`, `crazyflie_lee`, `crazyflie_mellinger` or "
           "`crazyflie_pid`; a quadrotor team planned jointly without the section: indi");
    v.custom("gains", "mapping", "the controller's named gains, checked before planning");
    v.boolean("drag_compensation", drag_compensation,
              "rotor drag in the flatness feed-forward (geometric and indi)");
    v.custom("thrust_map", "choice",
             "crazyflie_*: `battery_compensated` (upstream, default) or `pwm_quadratic` "
             "(IMRCLab's 2024 fork)");
    v.custom("thrust_map_coefficients", "[x, y, z]",
             "pwm_quadratic's normalised PWM d00 + d10 g + d20 g^2 of g grams a motor");
    v.custom("idle_thrust", "number",
             "crazyflie_*: PWM 0..65535 [0 battery_compensated, 10000 pwm_quadratic]");
    v.custom("platform", "choice",
             "crazyflie_*: `cf21bl` (default) or `cf2`, the power distribution's arm length and "
             "thrust-to-torque ratio");
  }
};

struct MotionSections {
  PlannerSection planner;
  TrajectorySection trajectory;
  ControllerSection controller;
};

}  // namespace cosim
