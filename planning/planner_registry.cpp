#include "planning/planner_registry.h"

#include <algorithm>
#include <map>

#include "core/input_error.h"
#include "core/name_suggestion.h"
#include "core/owner_list.h"
#include "planning/grid/grid_planners.h"
#include "planning/grid/grid_world_planner.h"
#include "planning/mapf/mapf_planner_registry.h"
#include "planning/navigation/navigation_planners.h"
#include "planning/sampling/sampling_planners.h"
#include "planning/swarm/acs_maklink.h"
#include "planning/swarm/grid_walk_planners.h"
#include "planning/swarm/msac_saco_planners.h"

namespace cosim {

// Each family's registration lives beside its planners: the family's header declares
// `void register<Group>Planners(PlannerRegistry&)`; include it above and call it below. The
// order of the calls is the order of `cosim plan --list`.

const PlannerRegistry& PlannerRegistry::instance() {
  static const PlannerRegistry registry = [] {
    PlannerRegistry r;
    // register<Group>Planners(r) calls go here, one per group of planners.
    registerSamplingPlanners(r);
    registerGridPlanners(r);
    registerMsacSacoPlanners(r);
    registerNavigationPlanners(r);
    registerGridWalkPlanners(r);
    registerAcsMaklinkPlanner(r);
    return r;
  }();
  return registry;
}

void PlannerRegistry::addGridPlanner(const std::string& name, const std::string& family,
                                     const std::string& summary, GridPlannerFactory make_grid) {
  PlannerEntry e;
  e.name = name;
  e.family = family;
  e.summary = summary;
  e.make_grid = make_grid;
  e.make = [make_grid](ParamSet& params) -> std::unique_ptr<Planner> {
    const double resolution = params.getDouble("resolution", 0.5, 0.01, 100.0);
    auto planner = make_grid(params);
    // "exact" (default where the planner checks edges against the obstacles): a cell is blocked
    // iff the vehicle cannot stand at its centre; "cell": if any point of it is near an obstacle
    // (conservative, closes gaps narrower than a cell; the default of the other grid planners);
    // "centre": only if its centre is strictly inside an inflated obstacle, edges unchecked
    // (seed 003's grid, for reproducing its point-mass plans).
    std::vector<std::string> allowed = {"cell", "centre"};
    if (planner->checksSegments()) allowed.insert(allowed.begin(), "exact");
    const std::string blocking = params.getString("cell_blocking", allowed.front(), allowed);
    return std::make_unique<GridWorldPlanner>(std::move(planner), resolution,
                                              blocking == "exact" ? OccupancyGrid::Blocking::Exact
                                              : blocking == "centre"
                                                  ? OccupancyGrid::Blocking::Centre
                                                  : OccupancyGrid::Blocking::AnyPoint);
  };
  add(std::move(e));
}

const PlannerEntry* PlannerRegistry::find(const std::string& name) const {
  for (const auto& e : entries_)
    if (e.name == name) return &e;
  return nullptr;
}

namespace {
const PlannerEntry& findOrThrow(const std::string& name, const ParamSet& params,
                                const std::string& place, bool grid_only) {
  const PlannerEntry* entry = PlannerRegistry::instance().find(name);
  if (entry && (!grid_only || entry->make_grid)) return *entry;
  const std::string kind = grid_only ? "grid planner" : "single-agent planner";
  for (const auto& team : mapfPlanners())
    if (team.name == name)
      throw InputError(params.file(), place,
                       "'" + name + "' is a team (multi-robot) planner, not a " + kind +
                           ": team planners are for `cosim mapf` and for `cosim run` on a "
                           "scenario of ground robots or of a quadrotor team");
  std::vector<std::string> known;
  for (const auto& e : PlannerRegistry::instance().entries())
    if (!grid_only || e.make_grid) known.push_back(e.name);
  std::string list;
  for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
  const std::string hint = didYouMean(name, known);
  throw InputError(params.file(), place,
                   "unknown " + std::string(grid_only ? "grid " : "") + "planner '" + name + "' (" +
                       (hint.empty() ? "" : hint + " ") +
                       "known: " + (list.empty() ? "none" : list) + ")");
}
}  // namespace

std::unique_ptr<GridPlanner> makeGridPlanner(const std::string& name, ParamSet& params,
                                             const std::string& place) {
  auto planner = findOrThrow(name, params, place, true).make_grid(params);
  params.requireAllUsed("planner '" + name + "'");
  return planner;
}

const std::vector<std::string>& allPlannerParameterNames() {
  // Each factory asks for its parameters by name with defaults: building every planner once
  // from an empty set lists them all.
  static const std::vector<std::string> names = [] {
    std::vector<std::string> all;
    for (const auto& e : PlannerRegistry::instance().entries()) {
      ParamSet probe("probe");
      e.make(probe);
      for (const auto& [k, v] : probe.effective())
        if (std::find(all.begin(), all.end(), k) == all.end()) all.push_back(k);
    }
    return all;
  }();
  return names;
}

namespace {
// Each parameter name some registered planner reads -> "planners a, b" (who reads it).
const std::map<std::string, std::string>& plannersByParameter() {
  static const std::map<std::string, std::string> takers = [] {
    std::map<std::string, std::vector<std::string>> names;
    for (const auto& e : PlannerRegistry::instance().entries()) {
      ParamSet probe("probe");
      e.make(probe);
      for (const auto& [k, v] : probe.effective()) names[k].push_back(e.name);
    }
    std::map<std::string, std::string> text;
    for (const auto& [k, planners] : names) text[k] = ownerList("planner", planners);
    return text;
  }();
  return takers;
}
}  // namespace

std::vector<ParamDeclaration> declaredParameters(const PlannerEntry& entry) {
  ParamSet probe("probe");
  entry.make(probe);
  return probe.declarations();
}

std::unique_ptr<Planner> makePlanner(const std::string& name, ParamSet& params,
                                     const std::string& place, std::vector<std::string>* ignored) {
  auto planner = findOrThrow(name, params, place, false).make(params);
  if (!ignored) {
    // `time_limit` is every planner's (the caller's search budget, checked by planVehicle),
    // whether or not this planner reads it itself.
    if (params.has("time_limit")) params.getDouble("time_limit", 30.0);
    params.requireAllUsed("planner '" + name + "'", plannersByParameter());
    return planner;
  }
  const auto unused =
      params.requireAllUsedExcept("planner '" + name + "'", allPlannerParameterNames());
  if (ignored) ignored->insert(ignored->end(), unused.begin(), unused.end());
  return planner;
}

}  // namespace cosim
