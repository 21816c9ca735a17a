#include "planning/mapf/mapf_planner_registry.h"

#include "core/input_error.h"
#include "planning/mapf/conflict_based_search.h"
#include "planning/mapf/cooperative_astar.h"
#include "planning/mapf/independent_astar.h"
#include "planning/mapf/lacam_planner.h"
#include "planning/mapf/local_repair_astar.h"
#include "planning/mapf/pibt_planner.h"
#include "planning/mapf/potential_field.h"
#include "planning/mapf/windowed_hca_star.h"
#include "core/name_suggestion.h"

namespace cosim {

namespace {

PriorityPolicy readPriorities(ParamSet& p, PriorityPolicy fallback) {
  return parsePriorityPolicy(
      p.getString("priorities", priorityPolicyName(fallback), {"fixed", "dynamic"}));
}

std::unique_ptr<MapfPlanner> makeCooperative(ParamSet& p, bool abstract_heuristic) {
  CooperativeAStarOptions o;
  o.abstract_heuristic = abstract_heuristic;
  o.priorities = readPriorities(p, o.priorities);
  o.max_expansions = p.getInt("max_expansions", 2'000'000, 1);
  return std::make_unique<CooperativeAStar>(o);
}

}  // namespace

const std::vector<MapfPlannerEntry>& mapfPlanners() {
  static const std::vector<MapfPlannerEntry> entries = {
      {"independent_astar", "every agent's own A* path, no coordination (baseline)",
       [](ParamSet&) -> std::unique_ptr<MapfPlanner> {
         return std::make_unique<IndependentAStar>();
       }},
      {"lra_star", "Local Repair A*: replan around robots met on the way (Silver 2005)",
       [](ParamSet& p) -> std::unique_ptr<MapfPlanner> {
         LocalRepairAStarOptions o;
         o.local_radius = p.getInt("local_radius", o.local_radius, 1, 100);
         o.agitation = p.getDouble("agitation", o.agitation, 0.0, 100.0);
         o.max_steps = p.getInt("max_steps", o.max_steps, 0);
         return std::make_unique<LocalRepairAStar>(o);
       }},
      {"ca_star", "Cooperative A*: prioritised space-time A* with a reservation table",
       [](ParamSet& p) { return makeCooperative(p, false); }},
      {"hca_star", "Hierarchical Cooperative A*: CA* with the Reverse Resumable A* heuristic",
       [](ParamSet& p) { return makeCooperative(p, true); }},
      {"whca_star", "Windowed HCA*: cooperative search in a sliding time window (Silver 2005)",
       [](ParamSet& p) -> std::unique_ptr<MapfPlanner> {
         WindowedHcaStarOptions o;
         o.window = p.getInt("window", o.window, 1, 10000);
         o.replan_every = p.getInt("replan_every", o.replan_every, 0, 10000);
         o.priorities = readPriorities(p, o.priorities);
         o.max_steps = p.getInt("max_steps", o.max_steps, 0);
         o.max_expansions = p.getInt("max_expansions", static_cast<int>(o.max_expansions), 1);
         return std::make_unique<WindowedHcaStar>(o);
       }},
      {"cbs", "Conflict-Based Search: optimal sum of costs (Sharon et al. 2015)",
       [](ParamSet& p) -> std::unique_ptr<MapfPlanner> {
         ConflictBasedSearchOptions o;
         o.max_nodes = p.getInt("max_nodes", static_cast<int>(o.max_nodes), 1);
         o.max_expansions = p.getInt("max_expansions", static_cast<int>(o.max_expansions), 1);
         o.bypass = p.getBool("bypass", o.bypass);
         return std::make_unique<ConflictBasedSearch>(o);
       }},
      {"lacam", "LaCAM*: complete, anytime, eventually optimal; thousands of agents (Okumura 2023)",
       [](ParamSet& p) -> std::unique_ptr<MapfPlanner> {
         LacamOptions o;
         o.anytime = p.getBool("anytime", o.anytime);
         o.refine_iterations = p.getInt("refine_iterations", 0, 0);
         o.swap = p.getBool("swap", o.swap);
         o.restart_rate = p.getDouble("restart_rate", o.restart_rate, 0.0, 1.0);
         o.max_memory_bytes = static_cast<std::size_t>(p.getInt("max_memory_mb", 1024, 16, 1 << 20))
                              << 20;
         return std::make_unique<LacamPlanner>(o);
       }},
      {"pibt", "PIBT: priority inheritance with backtracking, step by step (Okumura et al. 2022)",
       [](ParamSet& p) -> std::unique_ptr<MapfPlanner> {
         PibtPlannerOptions o;
         o.swap = p.getBool("swap", o.swap);
         o.max_steps = p.getInt("max_steps", o.max_steps, 0);
         return std::make_unique<PibtPlanner>(o);
       }},
      {"potential_field", "artificial potential field, step by step (baseline; local minima)",
       [](ParamSet& p) -> std::unique_ptr<MapfPlanner> {
         PotentialFieldOptions o;
         o.attraction = p.getDouble("attraction", o.attraction, 0.0, 1e6);
         o.repulsion = p.getDouble("repulsion", o.repulsion, 0.0, 1e6);
         o.influence_radius = p.getDouble("influence_radius", o.influence_radius, 1.0, 100.0);
         o.max_steps = p.getInt("max_steps", o.max_steps, 0);
         return std::make_unique<PotentialField>(o);
       }},
  };
  return entries;
}

std::vector<ParamDeclaration> declaredParameters(const MapfPlannerEntry& entry) {
  ParamSet probe("probe");
  entry.make(probe);
  return probe.declarations();
}

bool isMapfPlanner(const std::string& name) {
  for (const auto& e : mapfPlanners())
    if (e.name == name) return true;
  return false;
}

std::unique_ptr<MapfPlanner> makeMapfPlanner(const std::string& name, ParamSet& params,
                                             const std::string& place) {
  for (const auto& e : mapfPlanners()) {
    if (e.name != name) continue;
    auto planner = e.make(params);
    params.requireAllUsed("planner '" + name + "'");
    return planner;
  }
  std::vector<std::string> names;
  std::string known;
  for (const auto& e : mapfPlanners()) {
    names.push_back(e.name);
    known += (known.empty() ? "" : ", ") + e.name;
  }
  const std::string hint = didYouMean(name, names);
  throw InputError(params.file(), place,
                   "unknown multi-robot planner '" + name + "' (" +
                       (hint.empty() ? "" : hint + " ") + "known: " + known + ")");
}

}  // namespace cosim
