#pragma once
// The first stage of a run: what a scenario asks for, with the defaults that depend on the kind
// of run resolved. Which vehicles are ground robots (driven by the top-level planner, trajectory
// and controller sections) and which are quadrotors (driven by the top-level sections too, or by
// the `aerial` sections when they fly over robots); how each group gets its plan; and the
// defaults of a quadrotor team (its controller and trajectory mode).
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "sim/scenario.h"

namespace cosim {

// How a group of vehicles gets its plan.
enum class Planning {
  Alone,      // each vehicle its own single-agent plan, or its given waypoints (no planner)
  Team,       // all together, by a multi-robot (MAPF) planner
  Navigator,  // one robot, decided step by step while it drives (rna, wf_rna, d_star_lite)
};

struct RunSetup {
  std::vector<std::size_t> robots;      // indices into scenario.vehicles, in order
  std::vector<std::size_t> quadrotors;  // likewise
  Planning robot_planning = Planning::Alone;
  Planning quadrotor_planning = Planning::Alone;
  // The quadrotors' sections when they fly over robots: the scenario with the `aerial` planner,
  // trajectory and controller in place of the top-level ones (which drive the robots).
  std::optional<Scenario> aerial;

  // The kind the top-level sections drive: the ground robots if there are any (moving
  // obstacles need them; the run is the ground loop), else the quadrotors (the flight loop).
  VehicleKind primaryKind() const {
    return robots.empty() ? VehicleKind::Quadrotor : VehicleKind::GroundRobot;
  }
  // The vehicles the top-level sections drive: metrics.json's top-level figures are theirs.
  const std::vector<std::size_t>& primary() const { return robots.empty() ? quadrotors : robots; }
  // The scenario as the quadrotors' planner, trajectory and controller see it.
  const Scenario& quadrotorSections(const Scenario& scenario) const {
    return aerial ? *aerial : scenario;
  }
};

// True if the scenario has a ground robot, or moving obstacles.
bool isGroundRun(const Scenario& scenario);

// The navigators, which drive one robot deciding step by step: rna, wf_rna and d_star_lite.
bool isNavigatorName(const std::string& name);

// Sorts the vehicles, picks each group's planning, and resolves in `scenario` the defaults of
// its kind of run (a quadrotor team flies minimum-snap trajectories, under indi without a
// controller section; a point-mass plan keeps no margin). Throws InputError for a scenario no
// run can serve: moving obstacles without ground robots, disturbances without quadrotors, a
// navigator for several robots, a team or unknown planner for quadrotors over robots.
RunSetup resolveRun(Scenario& scenario, bool plan_as_point_mass);

}  // namespace cosim
