#pragma once
// The first stage of a run: what a scenario asks for, with the defaults that depend on the kind
// of run resolved into a value of its own (the loaded Scenario stays as the file said). Which
// vehicles are ground robots (driven by the top-level planner, trajectory and controller sections)
// and which are quadrotors (driven by the top-level sections too, or by the `aerial` sections when
// they fly over robots); how each group gets its plan; and the defaults of a quadrotor team (its
// controller and trajectory mode).
#include <cstddef>
#include <string>
#include <vector>

#include "sim/motion_sections.h"
#include "sim/error_reference.h"
#include "sim/scenario.h"

namespace cosim {

// How a group of vehicles gets its plan.
enum class Planning {
  Alone,      // each vehicle its own single-agent plan, or its given waypoints (no planner)
  Team,       // all together, by a multi-robot (MAPF) planner
  Navigator,  // one robot, decided step by step while it drives (rna, wf_rna, d_star_lite)
};

// One vehicle of the run as resolved: what it is, how it gets its plan, and what its tracking
// error is measured against (its sections are RunSetup::sectionsOf).
struct VehicleSetup {
  VehicleKind kind = VehicleKind::Quadrotor;
  Planning planning = Planning::Alone;
  ErrorReference error_reference = ErrorReference::PlannedPath;
};

struct RunSetup {
  std::vector<VehicleSetup> vehicles;   // one per scenario vehicle, in order
  std::vector<std::size_t> robots;      // indices into scenario.vehicles, in order
  std::vector<std::size_t> quadrotors;  // likewise
  Planning robot_planning = Planning::Alone;
  Planning quadrotor_planning = Planning::Alone;
  // The robots' sections: the top-level ones (a run with ground robots).
  MotionSections robot_sections;
  // The quadrotors' sections: over robots the `aerial` ones, else the top-level ones; with the
  // defaults of their kind of run resolved (a team's controller and trajectory mode, a
  // point-mass plan's margin).
  MotionSections quadrotor_sections;

  // A run with ground robots (moving obstacles need them) runs the ground loop; a run of
  // quadrotors alone the flight loop.
  // Ground robots when there are any (the top-level sections are theirs), else quadrotors.
  VehicleKind primaryKind() const {
    return robots.empty() ? VehicleKind::Quadrotor : VehicleKind::GroundRobot;
  }
  // The vehicles the top-level sections drive: metrics.json's top-level figures are theirs.
  const std::vector<std::size_t>& primary() const { return robots.empty() ? quadrotors : robots; }
  // The sections of the vehicles the top-level sections drive (primary()).
  const MotionSections& primarySections() const {
    return robots.empty() ? quadrotor_sections : robot_sections;
  }
  // The planner, trajectory and controller sections that drive vehicle v, as resolved.
  const MotionSections& sectionsOf(std::size_t v) const {
    return vehicles[v].kind == VehicleKind::GroundRobot ? robot_sections : quadrotor_sections;
  }
};

// True if the scenario has a ground robot, or moving obstacles.
bool isGroundRun(const Scenario& scenario);

// The navigators, which drive one robot deciding step by step: rna, wf_rna and d_star_lite.
bool isNavigatorName(const std::string& name);

// Sorts the vehicles, picks each group's planning and each vehicle's error reference, and resolves
// each group's sections with the defaults of its kind of run (a quadrotor team flies minimum-snap
// trajectories, under indi without a controller section; a point-mass plan keeps no margin). Throws
// InputError for a scenario no run can serve: moving obstacles without ground robots, disturbances
// without quadrotors, a navigator for several robots, a team or unknown planner for quadrotors over
// robots.
RunSetup resolveRun(const Scenario& scenario, bool plan_as_point_mass);

}  // namespace cosim
