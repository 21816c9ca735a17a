#pragma once
// Planners by name (the names a scenario's `planner.name` takes). Each planner family registers
// its planners from its own file through a register*Planners function listed in
// planner_registry.cpp.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "core/param_set.h"
#include "planning/grid/grid_planner.h"
#include "planning/planner.h"

namespace cosim {

// Builds a planner, reading its parameters from `params` (unknown names are then an error).
using PlannerFactory = std::function<std::unique_ptr<Planner>(ParamSet& params)>;
// Grid planners also have a grid-level factory, used by `cosim grid-bench` on MovingAI maps.
using GridPlannerFactory = std::function<std::unique_ptr<GridPlanner>(ParamSet& params)>;

struct PlannerEntry {
  std::string name;
  std::string family;  // "grid", "sampling", "swarm", ...
  std::string summary;
  PlannerFactory make;
  GridPlannerFactory make_grid;  // empty for planners that do not search a grid
};

class PlannerRegistry {
 public:
  static const PlannerRegistry& instance();
  void add(PlannerEntry entry) { entries_.push_back(std::move(entry)); }
  // Registers a grid planner for both uses: on grids directly, and on worlds through
  // GridWorldPlanner (which reads the `resolution` parameter, metres per cell).
  void addGridPlanner(const std::string& name, const std::string& family,
                      const std::string& summary, GridPlannerFactory make_grid);
  const PlannerEntry* find(const std::string& name) const;
  const std::vector<PlannerEntry>& entries() const { return entries_; }

 private:
  std::vector<PlannerEntry> entries_;
};

// Throws InputError (from params.file()) for an unknown name or unknown/invalid parameters.
std::unique_ptr<GridPlanner> makeGridPlanner(const std::string& name, ParamSet& params,
                                             const std::string& place = "--planner");
// Every parameter must be one the planner takes. Without `ignored` a parameter of another planner
// is an error naming the planners that take it and listing this one's (a scenario's `--set
// planner.step=1` with theta_star must not be silently dropped). With `ignored` (plan-bench, which
// gives every planner it compares the scenario's parameters) such a parameter is added to it
// instead; a name no planner takes is an error either way (a misspelling).
std::unique_ptr<Planner> makePlanner(const std::string& name, ParamSet& params,
                                     const std::string& place = "key planner.name",
                                     std::vector<std::string>* ignored = nullptr);

// Every parameter name some registered planner reads.
const std::vector<std::string>& allPlannerParameterNames();

// The parameters `entry`'s planner reads, in the order it reads them, with the defaults and
// ranges it declares when built from an empty set (so they are the values it really uses).
std::vector<ParamDeclaration> declaredParameters(const PlannerEntry& entry);

}  // namespace cosim
