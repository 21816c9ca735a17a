#include "run/scenario_checks.h"

#include <sstream>

#include "control/controller_factory.h"
#include "core/input_error.h"
#include "core/input_file.h"
#include "planning/mapf/mapf_planner_registry.h"
#include "planning/planner_registry.h"
#include "run/navigation_driver.h"
#include "run/quadrotor_team_planning.h"
#include "run/record/run_setup.h"
#include "run/run_pilots.h"
#include "run/scenario_planning.h"
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
  if (s.motion.planner.name.empty())
    throw InputError(s.file, "key planner", "no planner named (use --planner NAME)");
  ParamSet params = plannerParameters(s.motion.planner);
  params.getDouble("time_limit", 30.0, 0.001, kMaxPlannerTimeLimit);  // read by planVehicle
  makePlanner(s.motion.planner.name, params, "key planner.name");
}

// The controllers' gains, read as the run reads them after planning: a misspelt or out-of-range
// gain is found before a planner spends its time limit (20 s of rrt_star), not after. The
// quadrotors' controller is built once (no gain's valid range depends on the airframe, so the
// default one serves); the ground robots' gains are read as either drive reads them.
void checkControllers(const Scenario& s) {
  const RunSetup setup = resolveRun(s, false);
  if (!setup.robots.empty()) checkGroundControllerGains(setup.robot_sections.controller.gains);
  if (setup.quadrotors.empty()) return;
  const ControllerSection& c = setup.quadrotor_sections.controller;
  ParamSet gains = c.gains;
  makeFlightController(c.name, gains, QuadrotorParams{}, c.drag_compensation);
}

}  // namespace

void checkRunPlanners(const Scenario& s) {
  checkControllers(s);
  const auto single = [](const PlannerSection& section, const std::string& key) {
    const std::string& name = section.name;
    if (name.empty()) return;
    ParamSet p = plannerParameters(section);
    p.getDouble("time_limit", 30.0, 0.001, kMaxPlannerTimeLimit);  // read by planVehicle
    makePlanner(name, p, key);
  };
  if (!isGroundRun(s))
    return isMapfPlanner(s.motion.planner.name) ? checkQuadrotorTeamPlanner(s)
                                                : single(s.motion.planner, "key planner.name");
  const std::string& name = s.motion.planner.name;
  ParamSet p = s.motion.planner.params;
  if (isNavigatorName(name)) {
    p.getDouble("resolution", 0.5, 0.01, 100.0);
    makeNavigator(name, p);
    p.requireAllUsed("planner '" + name + "' (in cosim run: resolution and sight)");
  } else if (isMapfPlanner(name)) {
    if (!s.grid_map.present()) p.getDouble("resolution", 0.5, 0.01, 100.0);
    p.getInt("connectivity", 4, 4, 8);
    p.getDouble("time_limit", 30.0, 0.001, kMaxPlannerTimeLimit);
    makeMapfPlanner(name, p, "planner.name");
  } else {
    single(s.motion.planner, "key planner.name");
  }
  if (!s.aerial.planner.name.empty()) {
    if (!PlannerRegistry::instance().find(s.aerial.planner.name))
      throw InputError(s.file, "aerial.planner.name",
                       "unknown single-agent planner '" + s.aerial.planner.name + "'");
    single(s.aerial.planner, "key aerial.planner.name");
  }
}

std::string scenarioKeyPlace(const std::string& path, const std::vector<std::string>& overrides,
                             const std::string& key) {
  for (auto o = overrides.rbegin(); o != overrides.rend(); ++o) {
    const std::string assigned = o->substr(0, o->find('='));
    if (key.compare(0, assigned.size(), assigned) == 0 &&
        (key.size() == assigned.size() || key[assigned.size()] == '.' ||
         key[assigned.size()] == '['))
      return setAssignmentPlace(*o) + ", key " + key;
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

Scenario loadScenarioForPlan(const std::string& path, std::vector<std::string> overrides,
                             const std::string& planner) {
  if (planner.empty()) return loadCheckedScenario(path, overrides, PlannerUse::FirstVehicle);
  const std::string assignment = "planner.name=" + planner;
  overrides.push_back(assignment);
  try {
    return loadCheckedScenario(path, overrides, PlannerUse::FirstVehicle);
  } catch (const InputError& e) {
    if (e.place() != setAssignmentPlace(assignment) + ", key planner.name") throw;
    throw InputError(e.file(), "--planner " + planner, e.problem());
  }
}

}  // namespace cosim
