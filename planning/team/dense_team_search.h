#pragma once
// A quadrotor team's paths on a roadmap finer than the separation ellipsoid (dense_roadmap.h),
// where an agent's vertex blocks every vertex its ellipsoid reaches and moves conflict by their
// swept ellipsoids (ellipsoid_reservations.h). One-agent-per-vertex searches (LaCAM, PIBT) do
// not model that, so the team is planned by prioritised planning (Erdmann and Lozano-Perez 1987;
// Silver's Cooperative A*, 2005): agents in priority order, each by A* in space and time around
// the ones before it, resting at its goal for ever once it arrives. The first priorities sort
// the agents by their distance to go, longest first; an agent that finds no path is raised above
// all others and the team planned again (dynamic priorities), at most once per agent.
//
// Every pair of the result keeps the separation at every step and along every move flown in
// lock-step (linear in a common progress), the property the continuous-time smoothing relies on.
#include <Eigen/Core>
#include <map>
#include <string>
#include <vector>

#include "core/stop_token.h"
#include "planning/mapf/mapf_graph.h"
#include "planning/planner_status.h"
#include "planning/team/separation_ellipsoid.h"

namespace cosim {

struct DenseTeamQuery {
  const MapfGraph* graph = nullptr;
  const std::vector<Eigen::Vector3d>* positions = nullptr;  // per vertex, m
  Eigen::Vector3d pitch = Eigen::Vector3d::Ones();          // the lattice's, m
  SeparationEllipsoid ellipsoid;
  double separation = 1.5;
  std::vector<int> starts, goals;  // vertices
  long max_expansions_per_agent = 400'000;
  const StopToken* deadline = nullptr;
};

struct DenseTeamResult {
  bool success = false;
  PlannerStatus status = PlannerStatus::Unknown;
  std::string message;
  std::vector<std::vector<int>> paths;     // per agent, its vertex at every step (same length)
  std::map<std::string, double> counters;  // expansions, restarts
};

DenseTeamResult planDenseTeam(const DenseTeamQuery& query);

// The closest ellipsoidal distance between any two agents over the lock-step plan (every step
// and every move), by all pairs: an independent check of planDenseTeam's result.
double closestLockStepDistance(const std::vector<std::vector<int>>& paths,
                               const std::vector<Eigen::Vector3d>& positions,
                               const SeparationEllipsoid& ellipsoid);

}  // namespace cosim
