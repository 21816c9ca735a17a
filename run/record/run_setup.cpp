#include "run/record/run_setup.h"

#include <algorithm>

#include "control/indi_controller.h"
#include "core/input_error.h"
#include "planning/mapf/mapf_planner_registry.h"
#include "planning/planner_registry.h"

namespace cosim {

namespace {

// Over ground robots each quadrotor plans alone: aerial.planner.name must be a single-agent
// planner (a team planner plans quadrotor-only scenarios).
void checkAerialPlanner(const Scenario& s) {
  const std::string& name = s.aerial.planner.name;
  if (name.empty() || PlannerRegistry::instance().find(name)) return;
  std::string known;
  for (const auto& e : PlannerRegistry::instance().entries())
    known += (known.empty() ? "" : ", ") + e.name;
  throw InputError(s.file, "aerial.planner.name",
                   "unknown single-agent planner '" + name + "' (known: " + known + ")");
}

void resolveGroundRun(const Scenario& s, RunSetup& setup) {
  if (s.disturbances.any() && setup.quadrotors.empty())
    throw InputError(s.file, "disturbances",
                     "wind, rotor drag and ground effect act on quadrotors; this scenario has "
                     "none (ground robots feel no disturbances)");
  const std::string& name = s.motion.planner.name;
  setup.robot_planning = isNavigatorName(name) ? Planning::Navigator
                         : isMapfPlanner(name) ? Planning::Team
                                               : Planning::Alone;
  if (setup.robot_planning == Planning::Navigator && setup.robots.size() != 1)
    throw InputError(s.file, "planner.name", "navigators (" + name + ") drive one robot");
  checkAerialPlanner(s);
  setup.robot_sections = s.motion;
  setup.quadrotor_sections = s.aerial;
}

// A quadrotor team whose members all fly given references is not planned (each flies its own);
// a team planner plans all of a team or none of it, so a team with some references is refused.
bool flyGivenReferences(const Scenario& s) {
  std::size_t given = 0;
  for (const VehicleSpec& v : s.vehicles) given += v.reference ? 1 : 0;
  if (given == 0) return false;
  if (given == s.vehicles.size()) return true;
  for (std::size_t i = 0; i < s.vehicles.size(); ++i)
    if (s.vehicles[i].reference)
      throw InputError(s.file, "vehicles[" + std::to_string(i) + "].reference",
                       "team planner '" + s.motion.planner.name +
                           "' plans every quadrotor together: give every vehicle a reference, or "
                           "none (or use a single-agent planner, which plans each vehicle "
                           "without a reference alone)");
  return false;
}

// Quadrotors alone: the top-level sections are theirs. A team planner plans them together,
// unless every one flies a given reference.
void resolveQuadrotorRun(const Scenario& s, RunSetup& setup) {
  setup.quadrotor_sections = s.motion;
  if (!isMapfPlanner(s.motion.planner.name) || flyGivenReferences(s)) return;
  setup.quadrotor_planning = Planning::Team;
  // A quadrotor team flies in its members' downwash. Without a controller section it gets indi
  // rather than the single vehicle's cascade: measured on swarm32.yaml, cascade let a vehicle
  // sag about 0.2 m under another and break the planned separation (1 downwash violation),
  // while indi, geometric and dsl_pid kept it (closest 1.48, 1.17 and 1.30 ellipsoids).
  MotionSections& team = setup.quadrotor_sections;
  if (!s.motion.controller.given) team.controller.name = IndiController::kName;
  team.trajectory.mode =
      TrajectoryMode::MinimumSnap;  // what the team flies, whatever the file said
}

// A robot is measured against its timed plan; a quadrotor against its trajectory when it flies
// one in time (a trajectory mode of its sections, or a given reference), else against its path.
VehicleSetup vehicleSetup(const Scenario& s, const RunSetup& setup, std::size_t v) {
  VehicleSetup vehicle;
  vehicle.kind = s.vehicles[v].kind;
  if (vehicle.kind == VehicleKind::GroundRobot) {
    vehicle.planning = setup.robot_planning;
    vehicle.error_reference = ErrorReference::TimedPlan;
    return vehicle;
  }
  vehicle.planning = setup.quadrotor_planning;
  const bool in_time = s.vehicles[v].reference ||
                       setup.quadrotor_sections.trajectory.mode != TrajectoryMode::Waypoints;
  vehicle.error_reference = in_time ? ErrorReference::Trajectory : ErrorReference::PlannedPath;
  return vehicle;
}

}  // namespace

bool isGroundRun(const Scenario& s) {
  if (!s.moving_obstacles.empty()) return true;
  return std::any_of(s.vehicles.begin(), s.vehicles.end(),
                     [](const VehicleSpec& v) { return v.kind == VehicleKind::GroundRobot; });
}

bool isNavigatorName(const std::string& name) {
  return name == "rna" || name == "wf_rna" || name == "d_star_lite";
}

RunSetup resolveRun(const Scenario& s, bool plan_as_point_mass) {
  RunSetup setup;
  for (std::size_t v = 0; v < s.vehicles.size(); ++v)
    (s.vehicles[v].kind == VehicleKind::GroundRobot ? setup.robots : setup.quadrotors).push_back(v);
  if (!s.moving_obstacles.empty() && setup.robots.empty())
    throw InputError(s.file, "world.moving_obstacles",
                     "moving obstacles need ground robots (omni_base, diff_drive or a URDF): "
                     "quadrotors do not sense them");
  if (setup.primaryKind() == VehicleKind::GroundRobot)
    resolveGroundRun(s, setup);
  else
    resolveQuadrotorRun(s, setup);
  // Seed 003's reproduction plans for a point (run/run_pipeline.h): no margin either.
  if (plan_as_point_mass && setup.quadrotor_planning == Planning::Alone)
    setup.quadrotor_sections.planner.margin = 0.0;
  for (std::size_t v = 0; v < s.vehicles.size(); ++v)
    setup.vehicles.push_back(vehicleSetup(s, setup, v));
  return setup;
}

}  // namespace cosim
