#pragma once
// Windowed Hierarchical Cooperative A* (Silver 2005, "Cooperative Pathfinding", §5; seed 004
// §3.5, §4.4-4.5). The cooperative search looks only `window` steps ahead (other agents are
// respected through the reservation table inside the window, the true distance of Reverse
// Resumable A* estimates the rest); every agent, also one that has arrived, is planned again
// after window / 2 steps, so parked agents can step aside. Resting on the goal costs nothing.
#include "planning/mapf/mapf_planner.h"
#include "planning/mapf/priority_policy.h"

namespace cosim {

struct WindowedHcaStarOptions {
  // 8: the default of the seed's software (igrek51/coop-pathfinder, WHCASimulationParams
  // timeDimension); Silver used 8-32. The thesis suggests w = number of agents (§3.5).
  int window = 8;
  // Replanning period; 0 = window / 2 (Silver: "halfway through the window").
  int replan_every = 0;
  // Dynamic by default: the seed's own WHCA* variant raises blocked agents (§4.5), and on the
  // MAPF benchmarks it turns most fixed-order failures into successes (seed004-mapf-scaling).
  PriorityPolicy priorities = PriorityPolicy::kDynamic;
  // Executed time steps before giving up; 0 = the number of map cells (the seed's software
  // stops its effectiveness tests after width x height steps).
  int max_steps = 0;
  long max_expansions = 200'000;  // per windowed search
};

class WindowedHcaStar final : public MapfPlanner {
 public:
  explicit WindowedHcaStar(WindowedHcaStarOptions options) : options_(options) {}
  std::string name() const override { return "whca_star"; }
  MapfResult solve(const MapfQuery& query, const StopToken& stop) override;

 private:
  WindowedHcaStarOptions options_;
};

}  // namespace cosim
