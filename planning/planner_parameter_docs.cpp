#include "planning/planner_parameter_docs.h"

#include <map>
#include <utility>

namespace cosim {

namespace {

using Docs = std::map<std::string, std::string>;

// What a parameter means wherever it appears, unless the planner or its family says otherwise
// (below).
const Docs& commonDocs() {
  static const Docs docs = {
      // Grids (GridWorldPlanner and the grid searches).
      {"resolution", "metres per grid cell of the world's voxel grid"},
      {"cell_blocking",
       "which cells are blocked: exact (the vehicle cannot stand at the centre; edges checked "
       "against the obstacles), cell (any point of the cell near an obstacle), centre (Navratil "
       "2019's "
       "grid)"},
      {"connectivity", "moves per cell: 0 = all (8 in 2D, 26 in 3D), or 4/8 (2D), 6/18/26 (3D)"},
      {"corner_cutting", "a diagonal move needs only its target cell free (else its sides too)"},
      {"heuristic_weight", "weighted A*: h times this (1 = optimal)"},
      {"conditional_diagonal", "a diagonal step needs both side cells free (no corner cutting)"},
      // Sampling.
      {"step", "metres: the longest edge a tree or roadmap adds"},
      {"max_nodes", "node budget; 0 = run until the time limit (or the memory bound)"},
      {"mode",
       "1: stop at the first path; 2: keep improving it for time_limit s, or until max_nodes "
       "when that is set"},
      {"time_limit", "mode 2: seconds of improving once a path exists"},
      {"goal_bias", "probability of sampling the goal"},
      {"goal_tolerance", "metres: the goal is joined from a node this close"},
      {"shortcut", "shorten the final path by line-of-sight shortcuts"},
      {"neighbour_search",
       "nearest nodes by kdtree, or linear (every node, as Navratil 2019's MATLAB)"},
      {"rewire_radius", "metres: neighbours rewired around a new node; 0 = k-nearest (log n)"},
      {"choose_parent",
       "near: cheapest neighbour as parent (Karaman-Frazzoli); nearest_parent: Navratil 2019's "
       "Fig. 16"},
      {"max_tree_nodes", "RRT*FN: nodes kept (the childless node farthest from the goal goes)"},
      {"rewire_costs",
       "subtree: a rewired node's new cost reaches its descendants; node: only its own changes"},
      {"goal_reattach",
       "the goal moves to a node that reaches it more cheaply (false: it keeps its first parent)"},
      {"k", "roadmap neighbours joined per sample"},
      // Ant colonies and other swarms.
      {"ants", "ants per iteration"},
      {"iterations", "iterations (colony generations)"},
      {"alpha", "weight of the pheromone in an ant's choice"},
      {"beta", "weight of the heuristic in an ant's choice"},
      {"rho", "pheromone evaporation rate"},
      {"tau0", "initial pheromone"},
      {"smoothing_range", "path nodes ahead a smoothing shortcut may reach (1 = light smoothing)"},
      {"directions", "moves per cell: 4, 8, or the 16/24/32-cell extended neighbourhoods"},
      {"local_search", "staircase shortcuts on every path found"},
      // Navigation in a map seen through a field of view.
      {"sight", "cells: half-width of the square field of view"},
      {"prediction", "moving obstacles predicted at constant_velocity, or along their trajectory"},
      {"oscillation",
       "anti-oscillation: previous (a return to the last cell) or any (cycles at the view's edge)"},
      {"max_replans", "collision re-plans per step before waiting"},
      {"max_waits", "waits in a row before giving up"},
      // Team (MAPF) planners.
      {"priorities", "fixed planning order, or dynamic (an agent without a route is raised)"},
      {"max_expansions", "low-level search budget, expansions per search"},
      {"max_steps", "time steps before giving up; 0 = the number of map cells"},
      {"swap", "PIBT's swap technique (agents may swap places through a detour)"},
  };
  return docs;
}

// Where a planner or a family gives a shared name its own meaning.
const std::map<std::string, Docs>& specificDocs() {
  static const std::map<std::string, Docs> docs = {
      {"msac",
       {{"ants", "scout ants per group (one group from the start, one from the goal)"},
        {"iterations", "MAX: iterations of S_max steps before giving up"},
        {"s_max", "steps per iteration; 0 = N*N/2 with N the larger grid side (Pencik 2014)"},
        {"post_processing", "cycle removal and light smoothing of each path found"},
        {"tabu_version", "tabu list variant of Pencik 2014 (1, 2 or 3)"},
        {"keep_dead_ends", "dead-end marks carry over between iterations (Pencik 2014 §4.3.2)"},
        {"iteration_end",
         "meeting: an iteration ends when the two groups meet (Pencik 2014 §4.3); shorter_path: "
         "only when a meeting gives a shorter path than the best so far, else the scouts walk on "
         "to S_max"}}},
      {"saco",
       {{"gamma", "memory capacity: visited cells held as obstacles (0 = none)"},
        {"memory", "first: the first gamma cells visited; rolling: the last gamma (Pencik 2014)"},
        {"elitist_weight", "Elitist Ant System weight of the best path (0 = plain Ant System)"},
        {"smoothing", "light smoothing after the cycle removal"},
        {"sufficient_length", "stop once a path is this short, in cells (0 = off)"},
        {"sufficient_ratio", "stop once a path is this times the octile distance (0 = off)"},
        {"max_walk_factor", "a walk gives up after this many steps times the number of cells"}}},
      {"rna",
       {{"ants", "MSAC scout ants per group in each local plan"},
        {"iterations", "MSAC iterations in each local plan"}}},
      {"ant_grid",
       {{"evaporation", "pheromone evaporation rate (lambda)"},
        {"deposit", "pheromone the best ant deposits (Q)"},
        {"initial_pheromone", "pheromone on every cell at the start"},
        {"heading",
         "heuristic: turn_and_goal (turn and deviation from the goal line) or turn (the "
         "ant-algorithm lecture)"}}},
      {"mmas",
       {{"p_best", "probability of rebuilding the best path at convergence (sets tau_min)"},
        {"stall_iterations", "iterations without improvement before pheromone reinitialisation"},
        {"detour_offset",
         "heuristic 1 / (detour_offset + detour): a straight move's is 1 / this"}}},
      {"ga",
       {{"population", "chromosomes (paths) per generation"},
        {"generations", "generations"},
        {"crossover_probability", "probability that two parents cross"},
        {"mutation_probability", "probability that a child mutates"},
        {"guided_initial", "initial paths guided by the ants' heuristic (else uniform walks)"},
        {"shortening_mutation", "Tuncer-Yildirim mutation (else a random legal neighbour)"},
        {"local_search", "staircase shortcuts on every child (not in the ant-algorithm lecture)"}}},
      {"pso",
       {{"particles", "particles"},
        {"iterations", "iterations"},
        {"inertia", "inertia weight w of the velocity update"},
        {"c1", "cognitive weight (towards the particle's best)"},
        {"c2", "social weight (towards the swarm's best)"},
        {"v_max", "velocity clamp, per dimension"},
        {"goal_bias", "priority units per cell of octile distance to the goal (decoding)"}}},
      {"acs_maklink",
       {{"beta", "weight of the heuristic (closeness to the Dijkstra route's offsets)"},
        {"q0", "probability of the greedy choice (ACS pseudo-random proportional rule)"},
        {"levels", "offsets per MAKLINK line (11: 0, 0.1, ..., 1)"},
        {"circle_sides", "polygon sides for cylinders and spheres"}}},
      {"lra_star",
       {{"local_radius", "robots within this Chebyshev distance count as obstacles in a replan"},
        {"agitation", "random noise added to the heuristic per replan (breaks cycles)"}}},
      {"whca_star",
       {{"window", "time steps the cooperative search looks ahead"},
        {"replan_every", "steps executed between replans; 0 = window / 2"},
        {"max_expansions", "expansions per windowed search"}}},
      {"cbs",
       {{"max_nodes", "constraint-tree node budget"},
        {"max_expansions", "low-level A* budget, expansions per search"},
        {"bypass", "take a conflict-free path of equal cost without splitting (ICAPS 2015)"}}},
      {"lacam",
       {{"anytime", "LaCAM*: keep improving after the first solution (false: LaCAM)"},
        {"refine_iterations", "iterations after the first solution; 0 = 5e6 / agents"},
        {"restart_rate", "probability of restarting the anytime search from the start"},
        {"max_memory_mb", "memory cap of the search, MB"}}},
      {"potential_field",
       {{"attraction", "weight of the goal's attraction"},
        {"repulsion", "weight of the repulsion of walls and other robots"},
        {"influence_radius", "cells: how far the repulsion reaches"}}},
  };
  return docs;
}

// Planners that read a family member's parameters under their own name.
const std::map<std::string, std::string>& sameDocsAs() {
  static const std::map<std::string, std::string> same = {{"sacodm", "saco"}};
  return same;
}

}  // namespace

std::string plannerParameterDescription(const std::string& planner, const std::string& parameter) {
  std::string owner = planner;
  if (const auto same = sameDocsAs().find(planner); same != sameDocsAs().end())
    owner = same->second;
  if (const auto p = specificDocs().find(owner); p != specificDocs().end())
    if (const auto d = p->second.find(parameter); d != p->second.end()) return d->second;
  const auto d = commonDocs().find(parameter);
  return d == commonDocs().end() ? "" : d->second;
}

}  // namespace cosim
