#include "planning/swarm/grid_walk_planners.h"

#include <string>

#include "core/input_error.h"
#include "planning/swarm/ant_grid.h"
#include "planning/swarm/genetic_algorithm.h"
#include "planning/swarm/grid_planner_factory.h"
#include "planning/swarm/mmas.h"
#include "planning/swarm/pso.h"

namespace cosim {

namespace {
int readDirections(ParamSet& params, int fallback) {
  const int d = params.getInt("directions", fallback, 4, 32);
  if (d != 4 && d != 8 && d != 16 && d != 24 && d != 32)
    throw InputError(params.file(), "parameter directions",
                     "'directions' must be 4, 8, 16, 24 or 32, got " + std::to_string(d));
  return d;
}

// The parameters ant_grid and mmas share: the colony's size and the exponents of the random
// proportional rule tau^alpha * eta^beta, with the same names and ranges.
template <class ColonyParams>
void readColony(ParamSet& params, ColonyParams& p, int max_iterations) {
  p.ants = params.getInt("ants", p.ants, 1, 10000);
  p.iterations = params.getInt("iterations", p.iterations, 1, max_iterations);
  p.alpha = params.getDouble("alpha", p.alpha, 0.0, 20.0);
  p.beta = params.getDouble("beta", p.beta, 0.0, 20.0);
}

AntGridParams readAntGridParams(ParamSet& params) {
  AntGridParams p;
  readColony(params, p, 100000);
  p.evaporation = params.getDouble("evaporation", p.evaporation, 0.0, 1.0);
  p.deposit = params.getDouble("deposit", p.deposit, 0.0, 1e6);
  p.initial_pheromone = params.getDouble("initial_pheromone", p.initial_pheromone, 1e-12, 1e6);
  p.directions = readDirections(params, p.directions);
  p.heading = params.getString("heading", "turn_and_goal", {"turn_and_goal", "turn"}) == "turn"
                  ? AntHeading::Turn
                  : AntHeading::TurnAndGoal;
  p.local_search = params.getBool("local_search", p.local_search);
  return p;
}

MmasParams readMmasParams(ParamSet& params) {
  MmasParams p;
  readColony(params, p, 60000);  // mmas.cpp keeps the iteration of a trail's last write in 16 bits
  p.rho = params.getDouble("rho", p.rho, 1e-6, 1.0);
  p.p_best = params.getDouble("p_best", p.p_best, 1e-9, 1.0);
  p.stall_iterations = params.getInt("stall_iterations", p.stall_iterations, 0, 60000);
  p.detour_offset = params.getDouble("detour_offset", p.detour_offset, 1e-6, 1e6);
  p.directions = readDirections(params, p.directions);
  p.local_search = params.getBool("local_search", p.local_search);
  return p;
}

GeneticAlgorithmParams readGeneticAlgorithmParams(ParamSet& params) {
  GeneticAlgorithmParams p;
  p.population = params.getInt("population", p.population, 2, 10000);
  p.generations = params.getInt("generations", p.generations, 0, 100000);
  p.crossover_probability =
      params.getDouble("crossover_probability", p.crossover_probability, 0.0, 1.0);
  p.mutation_probability =
      params.getDouble("mutation_probability", p.mutation_probability, 0.0, 1.0);
  p.directions = readDirections(params, p.directions);
  p.guided_initial = params.getBool("guided_initial", p.guided_initial);
  p.shortening_mutation = params.getBool("shortening_mutation", p.shortening_mutation);
  p.local_search = params.getBool("local_search", p.local_search);
  return p;
}

PsoParams readPsoParams(ParamSet& params) {
  PsoParams p;
  p.particles = params.getInt("particles", p.particles, 1, 10000);
  p.iterations = params.getInt("iterations", p.iterations, 1, 100000);
  p.inertia = params.getDouble("inertia", p.inertia, 0.0, 2.0);
  p.c1 = params.getDouble("c1", p.c1, 0.0, 10.0);
  p.c2 = params.getDouble("c2", p.c2, 0.0, 10.0);
  p.v_max = params.getDouble("v_max", p.v_max, 1e-6, 1e6);
  p.goal_bias = params.getDouble("goal_bias", p.goal_bias, 0.0, 1e6);
  p.directions = readDirections(params, p.directions);
  return p;
}
}  // namespace

void registerGridWalkPlanners(PlannerRegistry& r) {
  r.addGridPlanner("ant_grid", "swarm",
                   "the ant-algorithm lecture grid ant algorithm: node pheromone, heading "
                   "heuristic, black list, "
                   "best-ant update; 4/8/16/24/32 directions (plans on the start's layer)",
                   gridPlannerFactory<AntGrid>(readAntGridParams));
  r.addGridPlanner("mmas", "swarm",
                   "MAX-MIN Ant System (Stuetzle and Hoos 2000) on the grid, with staircase "
                   "local search (plans on the start's layer)",
                   gridPlannerFactory<Mmas>(readMmasParams));
  r.addGridPlanner(
      "ga", "swarm",
      "genetic algorithm on grid paths (the ant-algorithm lecture' comparison; Tuncer-Yildirim "
      "operators; plans on the start's layer)",
      gridPlannerFactory<GeneticAlgorithm>(readGeneticAlgorithmParams));
  r.addGridPlanner("pso", "swarm",
                   "particle swarm optimisation with priority encoding (Mohemmed et al. 2008) "
                   "on the grid (plans on the start's layer)",
                   gridPlannerFactory<Pso>(readPsoParams));
}

}  // namespace cosim
