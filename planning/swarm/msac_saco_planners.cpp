#include "planning/swarm/msac_saco_planners.h"

#include "planning/swarm/grid_planner_factory.h"

namespace cosim {

// Seed 000's experiments use unconditional diagonals; our default is the conditional move (no
// corner cutting), which keeps a vehicle of one cell clear of obstacle corners (GridWorldPlanner
// paths) and is the move set of the MovingAI optimal lengths. The reproductions set it false.
bool readConditionalDiagonal(ParamSet& params) {
  return params.getBool("conditional_diagonal", true);
}

MsacParams readMsacParams(ParamSet& params) {
  MsacParams p;
  p.ants = params.getInt("ants", p.ants, 1, 127);  // the uint8 tabu table holds 127 per group
  p.iterations = params.getInt("iterations", p.iterations, 1, 100000);
  p.s_max = params.getInt("s_max", p.s_max, 0, 2000000000);
  p.post_processing = params.getBool("post_processing", p.post_processing);
  p.smoothing_range = params.getInt("smoothing_range", p.smoothing_range, 1, 100000);
  p.conditional_diagonal = readConditionalDiagonal(params);
  p.tabu_version = params.getInt("tabu_version", p.tabu_version, 1, 3);
  p.keep_dead_ends = params.getBool("keep_dead_ends", p.keep_dead_ends);
  p.iteration_end =
      params.getString("iteration_end", "meeting", {"meeting", "shorter_path"}) == "meeting"
          ? MsacIterationEnd::Meeting
          : MsacIterationEnd::ShorterPath;
  return p;
}

SacoParams readSacoParams(ParamSet& params, const std::string& name) {
  SacoParams p;
  p.name = name;
  const bool dm = name == "sacodm";
  p.ants = params.getInt("ants", 3, 1, 100000);
  p.iterations = params.getInt("iterations", 10, 1, 100000);
  p.alpha = params.getDouble("alpha", 2.0, 0.0, 100.0);
  p.beta = params.getDouble("beta", dm ? 1.0 : 0.0, 0.0, 100.0);
  p.rho = params.getDouble("rho", 0.2, 1e-9, 1.0);
  p.tau0 = params.getDouble("tau0", 0.5, 1e-12, 1e12);
  // SACOdm defaults: the seed's best setting (Tables 6.11-6.14): gamma 1, rolling, EAS weight 1.
  p.gamma = params.getInt("gamma", dm ? 1 : 0, 0, 1000000);
  p.rolling_memory =
      params.getString("memory", dm ? "rolling" : "first", {"first", "rolling"}) == "rolling";
  p.elitist_weight = params.getDouble("elitist_weight", dm ? 1.0 : 0.0, 0.0, 1e6);
  p.smoothing = params.getBool("smoothing", true);
  p.smoothing_range = params.getInt("smoothing_range", 1, 1, 100000);
  p.conditional_diagonal = readConditionalDiagonal(params);
  p.sufficient_length = params.getDouble("sufficient_length", 0.0, 0.0, 1e12);
  p.sufficient_ratio = params.getDouble("sufficient_ratio", 0.0, 0.0, 1e6);
  p.max_walk_factor = params.getInt("max_walk_factor", p.max_walk_factor, 1, 1000000);
  return p;
}

void registerMsacSacoPlanners(PlannerRegistry& r) {
  r.addGridPlanner("msac", "swarm",
                   "Multi-Scout Ants Cooperation: two greedy scout-ant groups from start and goal "
                   "(Pencik 2014)",
                   gridPlannerFactory<Msac>(readMsacParams));
  r.addGridPlanner("saco", "swarm", "Simple Ant Colony Optimization, cell pheromone (Pencik 2014)",
                   gridPlannerFactory<Saco>(readSacoParams, std::string("saco")));
  r.addGridPlanner("sacodm", "swarm",
                   "SACO with distance (beta) and memory (gamma) terms (Pencik 2014)",
                   gridPlannerFactory<Saco>(readSacoParams, std::string("sacodm")));
}

}  // namespace cosim
