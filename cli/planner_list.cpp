#include "cli/planner_list.h"

#include <algorithm>
#include <vector>

#include "planning/mapf/mapf_planner_registry.h"
#include "planning/planner_parameter_docs.h"
#include "planning/planner_registry.h"

namespace cosim::cli {

namespace {

std::string padded(const std::string& text, std::size_t width) {
  return text.size() >= width ? text : text + std::string(width - text.size(), ' ');
}

// "    name = default  (range)  description", columns aligned within the planner.
std::string parameterLines(const std::string& planner,
                           const std::vector<ParamDeclaration>& declared) {
  std::size_t name_width = 0, value_width = 0;
  for (const ParamDeclaration& d : declared) {
    name_width = std::max(name_width, d.name.size());
    value_width = std::max(value_width, d.default_value.size() + d.range.size() + 3);
  }
  std::string out;
  for (const ParamDeclaration& d : declared)
    out += "    " + padded(d.name, name_width) + " = " +
           padded(d.default_value + " (" + d.range + ")", value_width) + "  " +
           plannerParameterDescription(planner, d.name) + "\n";
  if (declared.empty()) out += "    (no parameters)\n";
  return out;
}

}  // namespace

std::string plannerListText() {
  std::string out =
      "Single-vehicle planners (cosim plan, cosim run): set a parameter with --set "
      "planner.NAME=VALUE\nor under planner: in the scenario. Each also takes planner.time_limit "
      "(seconds for the whole\nsearch) and planner.margin (metres kept clear beyond the vehicle's "
      "radius). Shown: name = default\n(valid values) and what it does.\n";
  for (const PlannerEntry& e : PlannerRegistry::instance().entries())
    out += "\n" + e.name + "  [" + e.family + "]  " + e.summary + "\n" +
           parameterLines(e.name, declaredParameters(e));
  out +=
      "\nTeam (multi-robot) planners (cosim mapf --set NAME=VALUE; cosim run on a scenario of "
      "ground\nrobots or a quadrotor team, under planner:):\n";
  for (const MapfPlannerEntry& e : mapfPlanners())
    out += "\n" + e.name + "  [team]  " + e.summary + "\n" +
           parameterLines(e.name, declaredParameters(e));
  return out;
}

}  // namespace cosim::cli
