#pragma once
// Local Repair A* (Silver 2005, "Cooperative Pathfinding", §2; seed 004 §3.2.1, §4.3): every
// agent follows its own A* path, ignoring the others, until the next step is blocked by a robot;
// then it replans the rest of its route with the robots around it (within `local_radius`) as
// obstacles. To break cycles, each replan adds more random noise to the heuristic ("agitation").
// Agents move step by step through a StepArbiter, so the executed paths never collide; the plan
// fails when not all agents have arrived after `max_steps` steps. An agent that has arrived
// stays on its goal.
#include "planning/mapf/mapf_planner.h"

namespace cosim {

struct LocalRepairAStarOptions {
  int local_radius = 1;    // robots within this Chebyshev distance count as obstacles
  double agitation = 0.2;  // noise amplitude added per replan of the same agent (Silver §2)
  int max_steps = 0;       // 0 = the number of map cells
};

class LocalRepairAStar final : public MapfPlanner {
 public:
  explicit LocalRepairAStar(LocalRepairAStarOptions options) : options_(options) {}
  std::string name() const override { return "lra_star"; }
  MapfResult solve(const MapfQuery& query, const StopToken& stop) override;

 private:
  LocalRepairAStarOptions options_;
};

}  // namespace cosim
