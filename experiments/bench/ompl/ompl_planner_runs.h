#pragma once
// One run of an OMPL 1.5 geometric planner on our collision world, for `cosim plan-bench`: the
// problem is built the way our sampling planners see it (the same inflated obstacles through
// exact point and segment tests, the same sampling region, start and goal), the planner is
// seeded for the run, and the raw solution path (not simplified) comes back with OMPL's status.
// This is the only place besides cosim_bench_ompl that includes OMPL.
#include <Eigen/Core>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "planning/sampling/collision_world.h"

namespace cosim::omplbench {

// The names plan-bench accepts for OMPL's planners: ompl_rrt, ompl_rrt_connect, ompl_rrt_star,
// ompl_informed_rrt_star, ompl_prm.
const std::vector<std::string>& omplPlannerNames();
bool isOmplPlanner(const std::string& name);

// OMPL's own words for ompl::base::PlannerStatus values 0 .. TYPE_COUNT-1 (the "status" enum of
// its benchmark log), and its version ("1.5.2").
std::vector<std::string> omplStatusNames();
std::string omplVersion();
// The status values plan-bench reports for our planners, in OMPL's numbering.
int omplStatusExact();
int omplStatusTimeout();
int omplStatusApproximate();

struct OmplPlanRequest {
  std::string planner;  // one of omplPlannerNames()
  const CollisionWorld* world = nullptr;
  Eigen::Vector3d start = Eigen::Vector3d::Zero(), goal = Eigen::Vector3d::Zero();
  bool planar = false;  // plan in the plane z = start.z
  double time_limit_s = 1.0;
  std::uint32_t seed = 1;
  double range = 2.0;  // maximum edge length of the RRT family (our planners' `step`)
};

struct OmplPlanResult {
  int status = 0;      // an ompl::base::PlannerStatus::StatusType value
  bool exact = false;  // an exact solution (reaches the goal)
  std::vector<Eigen::Vector3d> path;
  double time_ms = 0.0;
  double graph_states = 0.0;                  // vertices of the planner's tree or roadmap
  std::map<std::string, std::string> params;  // the planner's parameters, as OMPL names them
};

OmplPlanResult planWithOmpl(const OmplPlanRequest& request);

}  // namespace cosim::omplbench
