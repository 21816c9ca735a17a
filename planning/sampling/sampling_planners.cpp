#include "planning/sampling/sampling_planners.h"

#include "planning/sampling/prm.h"
#include "planning/sampling/rrt.h"
#include "planning/sampling/rrt_connect.h"
#include "planning/sampling/rrt_star.h"

namespace cosim {

namespace {

// Parameter defaults. Where seed 003 gives a value it is used: step 2 m, rewire radius 4 m,
// N = 2000 generated nodes and mode 1 are its 3D parameter set 1 (Tables 6, 10, 14); the RRT*FN
// cap 400 = N/5 is the cap it recommends (and flies) for 3D map 3. The seed gives no goal bias
// (0.05 is OMPL's default), no goal tolerance (we connect to the goal from within one step) and
// no PRM neighbour count. Informed RRT* is the modern baseline, not a seed planner: it defaults
// to mode 2 (it exists to improve a path) and to k-nearest rewiring (rewire_radius = 0), as OMPL.
constexpr int kMaxNodesLimit = 10000000;  // bounds memory (about 1 GB at most)

SamplingOptions readCommon(ParamSet& p, double default_step, int default_mode, bool has_mode,
                           bool has_goal_bias, double default_goal_bias = 0.05) {
  SamplingOptions o;
  o.step = p.getDouble("step", default_step, 1e-3, 1e6);
  o.max_nodes = p.getInt("max_nodes", 2000, 2, kMaxNodesLimit);
  o.mode = has_mode ? p.getInt("mode", default_mode, 1, 2) : 1;
  o.goal_bias = has_goal_bias ? p.getDouble("goal_bias", default_goal_bias, 0.0, 1.0) : 0.0;
  o.goal_tolerance = has_goal_bias ? p.getDouble("goal_tolerance", o.step, 0.0, 1e6) : 0.0;
  o.shortcut = p.getBool("shortcut", false);
  // The RRT family's trees: "kdtree" (default) or "linear" (every node scanned, as seed 003's
  // MATLAB; same paths, the thesis's cost structure).
  if (has_goal_bias)
    o.linear_scan = p.getString("neighbour_search", "kdtree", {"kdtree", "linear"}) == "linear";
  return o;
}

RrtStarOptions readRrtStar(ParamSet& p, int default_mode, double default_radius, bool fixed_nodes,
                           bool informed) {
  RrtStarOptions o;
  o.common = readCommon(p, 2.0, default_mode, true, true);
  o.rewire_radius = p.getDouble("rewire_radius", default_radius, 0.0, 1e6);
  o.max_tree_nodes = fixed_nodes ? p.getInt("max_tree_nodes", 400, 2, kMaxNodesLimit) : 0;
  o.informed = informed;
  if (!informed)
    o.choose_parent = p.getString("choose_parent", "near", {"near", "nearest_parent"}) == "near"
                          ? ChooseParent::NearMin
                          : ChooseParent::NearestParent;
  return o;
}

// Seed 003's own RRT* (Fig. 16 choose-parent) with the settings of its tables: no goal bias (it
// names goal biasing but never says it used it); the goal is reached from within one step, as
// for the other planners (see sampling_planners.h).
RrtStarOptions readRrtStarThesis(ParamSet& p) {
  RrtStarOptions o;
  o.common = readCommon(p, 2.0, 1, true, true, 0.0);
  o.rewire_radius = p.getDouble("rewire_radius", 4.0, 1e-6, 1e6);
  o.max_tree_nodes = p.getInt("max_tree_nodes", 0, 0, kMaxNodesLimit);
  o.choose_parent = ChooseParent::NearestParent;
  return o;
}

}  // namespace

void registerSamplingPlanners(PlannerRegistry& r) {
  r.add({"prm",
         "sampling",
         "probabilistic roadmap: k nearest free edges, A* on the roadmap (params: step, "
         "max_nodes, mode, k, shortcut)",
         [](ParamSet& p) -> std::unique_ptr<Planner> {
           PrmOptions o;
           // PRM edges join existing samples, so they must be longer than RRT steps to connect
           // a roadmap of N = 2000 nodes in a 50 m world.
           o.common = readCommon(p, 5.0, 1, true, false);
           o.k = p.getInt("k", 10, 1, 1000);
           return std::make_unique<Prm>(o);
         },
         {}});
  r.add({"rrt",
         "sampling",
         "RRT, seed 003 (params: step, max_nodes, mode, goal_bias, goal_tolerance, shortcut)",
         [](ParamSet& p) -> std::unique_ptr<Planner> {
           return std::make_unique<Rrt>(readCommon(p, 2.0, 1, true, true));
         },
         {}});
  r.add({"rrt_star",
         "sampling",
         "RRT* (Karaman-Frazzoli choose-parent) with fixed rewire radius, seed 003 (params: step, "
         "rewire_radius, max_nodes, mode, goal_bias, goal_tolerance, choose_parent, shortcut)",
         [](ParamSet& p) -> std::unique_ptr<Planner> {
           return std::make_unique<RrtStar>(readRrtStar(p, 1, 4.0, false, false));
         },
         {}});
  r.add({"rrt_star_thesis",
         "sampling",
         "seed 003's own RRT* (its Fig. 16: a new node joins its nearest node's parent if visible, "
         "then rewires within rewire_radius), no goal bias; max_tree_nodes > 0 makes it seed "
         "003's RRT*FN (params: step, rewire_radius, max_nodes, mode, goal_bias, "
         "goal_tolerance, max_tree_nodes, neighbour_search, shortcut)",
         [](ParamSet& p) -> std::unique_ptr<Planner> {
           return std::make_unique<RrtStar>(readRrtStarThesis(p));
         },
         {}});
  r.add({"rrt_star_fn",
         "sampling",
         "RRT* with fixed nodes: removes the childless node farthest from the goal above "
         "max_tree_nodes, seed 003 (params: as rrt_star plus max_tree_nodes; choose_parent: "
         "nearest_parent is seed 003's own RRT*FN)",
         [](ParamSet& p) -> std::unique_ptr<Planner> {
           return std::make_unique<RrtStar>(readRrtStar(p, 1, 4.0, true, false));
         },
         {}});
  r.add({"rrt_connect",
         "sampling",
         "bidirectional RRT-Connect, first solution (params: step, max_nodes, shortcut)",
         [](ParamSet& p) -> std::unique_ptr<Planner> {
           return std::make_unique<RrtConnect>(readCommon(p, 2.0, 1, false, false));
         },
         {}});
  r.add({"informed_rrt_star",
         "sampling",
         "Informed RRT* (ellipsoidal sampling once a path exists); mode 2 and k-nearest rewiring "
         "(rewire_radius 0) by default (params: as rrt_star)",
         [](ParamSet& p) -> std::unique_ptr<Planner> {
           return std::make_unique<RrtStar>(readRrtStar(p, 2, 0.0, false, true));
         },
         {}});
}

}  // namespace cosim
