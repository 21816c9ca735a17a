#include "planning/sampling/sampling_planners.h"

#include "planning/sampling/prm.h"
#include "planning/sampling/rrt.h"
#include "planning/sampling/rrt_connect.h"
#include "planning/sampling/rrt_star.h"

namespace cosim {

namespace {

// Parameter defaults. Where seed 003 gives a value it is used: step 2 m, rewire radius 4 m and
// the RRT*FN cap 400 (= N/5, the cap it recommends and flies for 3D map 3) are its 3D parameter
// set 1 (Tables 6, 10, 14). Its node budget N and its mode 1 (stop at the first path) are not
// defaults: like OMPL's planners, ours run until their time limit, stopping at max_nodes only
// when it is set, and the anytime planners (the RRT*s) keep improving their path (mode 2) for
// `time_limit` seconds; the reproductions set N and the mode of each table. The seed gives no
// goal bias (0.05 is OMPL's default), no goal tolerance (we connect to the goal from within one
// step) and no PRM neighbour count. Informed RRT* is the modern baseline, not a seed planner: it
// defaults to k-nearest rewiring (rewire_radius = 0), as OMPL.
//
// The anytime planners' default time limit: OMPL's benchmarks give planners 1-10 s; 1 s keeps
// `cosim run` and sweeps quick and already leaves RRT* within a few percent of its limit on the
// bundled worlds. It applies once a first path exists; the search for one runs on to the run's
// own limit (planner.time_limit, read by the command line as well), so a hard world is not given
// up after 1 s.
constexpr double kAnytimeTimeLimitS = 1.0;
constexpr double kMaxTimeLimitS = 3600.0;

SamplingOptions readCommon(ParamSet& p, double default_step, int default_mode, bool has_mode,
                           bool has_goal_bias, double default_goal_bias = 0.05) {
  SamplingOptions o;
  o.step = p.getDouble("step", default_step, 1e-3, 1e6);
  o.max_nodes = p.getInt("max_nodes", 0, 0, kNodeMemoryBound);
  o.mode = has_mode ? p.getInt("mode", default_mode, 1, 2) : 1;
  // A node budget the user set is the stopping rule of mode 2 (seed 003's tables); without one,
  // improving stops at time_limit.
  if (o.mode == 2 && (o.max_nodes == 0 || p.has("time_limit")))
    o.improve_time_s = p.getDouble("time_limit", kAnytimeTimeLimitS, 1e-3, kMaxTimeLimitS);
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
  o.max_tree_nodes = fixed_nodes ? p.getInt("max_tree_nodes", 400, 2, kNodeMemoryBound) : 0;
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
  o.max_tree_nodes = p.getInt("max_tree_nodes", 0, 0, kNodeMemoryBound);
  o.choose_parent = ChooseParent::NearestParent;
  // The thesis's mode 2 barely shortens its paths; its two candidate causes, each switchable.
  o.propagate_rewire_costs =
      p.getString("rewire_costs", "subtree", {"subtree", "node"}) == "subtree";
  o.reattach_goal = p.getBool("goal_reattach", true);
  return o;
}

}  // namespace

void registerSamplingPlanners(PlannerRegistry& r) {
  r.add({"prm",
         "sampling",
         "probabilistic roadmap: k nearest free edges, A* on the roadmap (params: step, "
         "max_nodes, mode, time_limit, k, shortcut); first solution unless mode 2",
         [](ParamSet& p) -> std::unique_ptr<Planner> {
           PrmOptions o;
           // PRM edges join existing samples, so they must be longer than RRT steps to connect
           // a roadmap of a few thousand nodes in a 50 m world.
           o.common = readCommon(p, 5.0, 1, true, false);
           o.k = p.getInt("k", 10, 1, 1000);
           return std::make_unique<Prm>(o);
         },
         {}});
  r.add({"rrt",
         "sampling",
         "RRT, Navratil 2019, first solution unless mode 2 (params: step, max_nodes, mode, "
         "time_limit, "
         "goal_bias, goal_tolerance, shortcut)",
         [](ParamSet& p) -> std::unique_ptr<Planner> {
           return std::make_unique<Rrt>(readCommon(p, 2.0, 1, true, true));
         },
         {}});
  r.add({"rrt_star",
         "sampling",
         "RRT* (Karaman-Frazzoli choose-parent) with fixed rewire radius, Navratil 2019; anytime: "
         "improves for time_limit s (default 1), mode 1 stops at the first path (params: step, "
         "rewire_radius, max_nodes, mode, time_limit, goal_bias, goal_tolerance, choose_parent, "
         "shortcut)",
         [](ParamSet& p) -> std::unique_ptr<Planner> {
           return std::make_unique<RrtStar>(readRrtStar(p, 2, 4.0, false, false));
         },
         {}});
  r.add({"rrt_star_thesis",
         "sampling",
         "Navratil 2019's own RRT* (its Fig. 16: a new node joins its nearest node's parent if "
         "visible, "
         "then rewires within rewire_radius), no goal bias, mode 1 (first path) as the thesis; "
         "max_tree_nodes > 0 makes it Navratil 2019's RRT*FN (params: step, rewire_radius, "
         "max_nodes, mode, goal_bias, goal_tolerance, max_tree_nodes, neighbour_search, "
         "rewire_costs, goal_reattach, shortcut)",
         [](ParamSet& p) -> std::unique_ptr<Planner> {
           return std::make_unique<RrtStar>(readRrtStarThesis(p));
         },
         {}});
  r.add({"rrt_star_fn",
         "sampling",
         "RRT* with fixed nodes: removes the childless node farthest from the goal above "
         "max_tree_nodes, Navratil 2019 (params: as rrt_star plus max_tree_nodes; choose_parent: "
         "nearest_parent is Navratil 2019's own RRT*FN)",
         [](ParamSet& p) -> std::unique_ptr<Planner> {
           return std::make_unique<RrtStar>(readRrtStar(p, 2, 4.0, true, false));
         },
         {}});
  r.add({"rrt_connect",
         "sampling",
         "bidirectional RRT-Connect, first solution; runs until its time limit or max_nodes if set "
         "(params: step, max_nodes, shortcut)",
         [](ParamSet& p) -> std::unique_ptr<Planner> {
           return std::make_unique<RrtConnect>(readCommon(p, 2.0, 1, false, false));
         },
         {}});
  r.add({"informed_rrt_star",
         "sampling",
         "Informed RRT* (ellipsoidal sampling once a path exists); anytime as rrt_star, k-nearest "
         "rewiring (rewire_radius 0) by default (params: as rrt_star)",
         [](ParamSet& p) -> std::unique_ptr<Planner> {
           return std::make_unique<RrtStar>(readRrtStar(p, 2, 0.0, false, true));
         },
         {}});
}

}  // namespace cosim
