// Reads a scenario: the document (with its --set overrides applied) checked for unknown keys,
// then each section by its own reader (sim/scenario_sections.h), in the order that lets a section
// be checked against the ones before it.
#include "core/input_error.h"
#include "core/input_file.h"
#include "sim/declared_key_reader.h"
#include "sim/scenario.h"
#include "sim/scenario_overrides.h"
#include "sim/scenario_sections.h"
#include "sim/scenario_sensing.h"
#include "sim/yaml_document.h"
#include "sim/yaml_reader.h"

namespace cosim {

Scenario loadScenario(const std::string& path, const std::vector<std::string>& overrides) {
  return parseScenario(readInputFile(path, kMaxScenarioFileBytes, "scenario file"), path,
                       overrides);
}

// parseScenario without placing errors at their --set assignments.
// `dir`: where relative paths resolve; `reference_copies_dir`: see Scenario.
static Scenario parseScenarioText(const std::string& text, const std::string& file,
                                  const std::vector<std::string>& overrides,
                                  const std::filesystem::path& dir,
                                  const std::filesystem::path& reference_copies_dir) {
  const YamlReader r(file);
  YAML::Node root = loadYamlDocument(text, file);
  if (!root.IsDefined() || root.IsNull()) root = YAML::Node(YAML::NodeType::Map);
  for (const auto& o : overrides) applyYamlOverride(root, o);
  r.checkKeys(root, "",
              {"world", "vehicles", "planner", "trajectory", "controller", "aerial", "sim", "team",
               "disturbances", "sensors", "estimator", "model_error", "render"});

  Scenario s;
  s.file = file;
  s.effective_yaml = YAML::Dump(root) + "\n";
  s.reference_copies_dir = reference_copies_dir;
  s.motion.planner.params = ParamSet(file);
  s.motion.trajectory.params = ParamSet(file);
  s.motion.controller.gains = ParamSet(file);
  s.aerial.planner.params = ParamSet(file);
  s.aerial.trajectory.params = ParamSet(file);
  s.aerial.controller.gains = ParamSet(file);

  readWorldSection(r, root, dir, s);
  readVehiclesSection(r, root, dir, s);
  readMotionSections(r, root, overrides, s);
  checkVehiclePower(r, root, s);
  readSimSection(r, root, s);
  readDisturbancesSection(r, root, s);
  if (root["team"]) readDeclaredKeys(r, root["team"], "team", s.team);
  readSensingSections(r, root, s);
  readRenderSection(r, root, s);
  return s;
}

Scenario parseScenario(const std::string& text, const std::string& file,
                       const std::vector<std::string>& overrides) {
  try {
    return parseScenarioText(text, file, overrides, std::filesystem::path(file).parent_path(), {});
  } catch (const InputError& e) {
    throw placedAtOverride(e, file, overrides);
  }
}

Scenario parseRunFolderScenario(const std::string& text, const std::string& file,
                                const std::filesystem::path& base_dir,
                                const std::filesystem::path& run_dir) {
  return parseScenarioText(text, file, {}, base_dir, run_dir);
}

std::string runReferenceCopyName(std::size_t vehicle) {
  return "reference_" + std::to_string(vehicle) + ".csv";
}

}  // namespace cosim
