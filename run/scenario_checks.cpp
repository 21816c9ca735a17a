#include "run/scenario_checks.h"

#include <sstream>

#include "run/ground_run_pipeline.h"
#include "run/scenario_planning.h"
#include "core/input_error.h"
#include "core/input_file.h"
#include "planning/planner_registry.h"
#include "sim/yaml_document.h"
#include "sim/yaml_reader.h"

namespace cosim {

namespace {

// The planner's own name key for the places the planner checks use ("key planner.name",
// "planner.name", ...), or "" for an error about something else.
std::string plannerNameKey(const std::string& place) {
  for (const char* key : {"planner.name", "aerial.planner.name"})
    if (place == key || place == std::string("key ") + key) return key;
  return "";
}

void checkPlanners(const Scenario& s, PlannerUse use) {
  if (use == PlannerUse::Run) return checkRunPlanners(s);
  if (s.planner_name.empty())
    throw InputError(s.file, "key planner", "no planner named (use --planner NAME)");
  ParamSet params = s.planner_params;
  params.getDouble("time_limit", 30.0, 0.001, kMaxPlannerTimeLimit);  // read by planVehicle
  makePlanner(s.planner_name, params, "key planner.name");
}

}  // namespace

std::string scenarioKeyPlace(const std::string& path, const std::vector<std::string>& overrides,
                             const std::string& key) {
  for (auto o = overrides.rbegin(); o != overrides.rend(); ++o) {
    const std::string assigned = o->substr(0, o->find('='));
    if (key.compare(0, assigned.size(), assigned) == 0 &&
        (key.size() == assigned.size() || key[assigned.size()] == '.' ||
         key[assigned.size()] == '['))
      return "--set " + *o + ", key " + key;
  }
  // The file was loaded a moment ago: read it again to find the key's line.
  // (yaml-cpp's assignment would rebind the nodes, so the walk collects them instead.)
  std::vector<YAML::Node> chain{
      loadYamlDocument(readInputFile(path, kMaxScenarioFileBytes, "scenario file"), path)};
  std::stringstream parts(key);
  for (std::string part; std::getline(parts, part, '.');) {
    const YAML::Node& parent = chain.back();
    if (!parent.IsMap() || !parent[part]) return "key " + key;
    chain.push_back(parent[part]);
  }
  return YamlReader(path).place(chain.back(), key);
}

Scenario loadCheckedScenario(const std::string& path, const std::vector<std::string>& overrides,
                             PlannerUse use) {
  Scenario scenario = loadScenario(path, overrides);
  try {
    checkPlanners(scenario, use);
  } catch (const InputError& e) {
    const std::string key = plannerNameKey(e.place());
    if (key.empty()) throw e.inFile(path);
    throw InputError(path, scenarioKeyPlace(path, overrides, key), e.problem());
  }
  return scenario;
}

}  // namespace cosim
