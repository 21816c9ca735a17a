#pragma once
// The one small interface every single-vehicle planner implements (after OMPL's Planner):
// the problem (world, start, goal, vehicle size, limits) is separate from the planner, and a
// planner returns a path plus counters. Planners never see MuJoCo, YAML or rendering.
#include <cstdint>
#include <map>
#include <memory>
#include <string>

#include "planning/path.h"
#include "planning/planner_status.h"
#include "planning/world/world.h"

namespace cosim {

struct PlanningProblem {
  const World* world = nullptr;
  Eigen::Vector3d start = Eigen::Vector3d::Zero();
  Eigen::Vector3d goal = Eigen::Vector3d::Zero();
  // Vehicle radius plus safety margin: obstacles are grown by this much before planning, so the
  // vehicle's volume is accounted for (seed 003 ignored it and its flights hit obstacles).
  double inflation = 0.0;
  // Ground robots plan in the plane z = start.z (2D); UAVs plan in 3D.
  bool planar = false;
  double time_limit_s = 10.0;
  std::uint64_t seed = 1;
};

struct PlanResult {
  bool success = false;  // status == ExactSolution
  PlannerStatus status = PlannerStatus::Unknown;
  Path path;
  double time_ms = 0.0;
  // Planner-specific counters, e.g. expansions, los_checks, iterations, nodes.
  std::map<std::string, double> counters;
  // Why a plan failed ("no path", "time limit"), empty on success.
  std::string message;
};

class Planner {
 public:
  virtual ~Planner() = default;
  virtual std::string name() const = 0;
  // `stop` is the caller's StopToken (its own deadline and stop request; StopToken::untimed()
  // when it has none): the search ends when it expires or at problem.time_limit_s, whichever
  // comes first.
  virtual PlanResult solve(const PlanningProblem& problem, const StopToken& stop) = 0;
};

}  // namespace cosim
