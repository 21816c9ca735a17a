// The scenario key reference (docs/scenario_keys.md, "Every key") cannot drift from the loader:
// each of its rows lists exactly the keys the loader accepts in that section (asked of the loader
// itself, through the "allowed: ..." list of an unknown key), and the trajectory rows exactly the
// parameters the flight reads. A key added to the loader but not to the reference fails here, and
// so does a key the reference still lists after the loader dropped it. Its "Key by key" tables
// (each key's type, default, range and meaning) must be exactly what the settings structs declare
// (sim/scenario_key_docs.h); COSIM_UPDATE_KEY_DOCS=1 rewrites them from the declarations.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "core/input_error.h"
#include "sim/scenario.h"
#include "sim/scenario_key_docs.h"
#include "tests/support/cosim_command.h"

namespace cosim::test {
namespace {

namespace fs = std::filesystem;

// The user documentation's scenario key reference, relative to the project.
const char* const kKeyReference = "docs/scenario_keys.md";

// A scenario with one obstacle of each kind and two moving obstacles, so every section can be
// reached (moving obstacles with a quadrotor only are refused later, by the run, not the loader).
const std::string kScenario =
    "world:\n"
    "  bounds: {min: [0, 0, 0], max: [20, 20, 6]}\n"
    "  obstacles:\n"
    "    - {type: box, pos: [10, 10, 3], size: [2, 2, 6]}\n"
    "    - {type: cylinder, pos: [5, 15, 3], radius: 0.5, height: 6}\n"
    "    - {type: sphere, pos: [15, 5, 3], radius: 0.5}\n"
    "  moving_obstacles:\n"
    "    - {type: cylinder, radius: 0.3, height: 1, path: [[3, 10]]}\n"
    "    - {type: box, size: [0.5, 0.5, 1], path: [[17, 10]]}\n"
    "vehicles: [{name: uav1, model: cf2, start: [2, 2, 1], goal: [18, 18, 1]}]\n";

// The reference's row label of each section, and the path under which an unknown key is set there.
const std::vector<std::pair<std::string, std::string>> kLoaderSections = {
    {"(top level)", ""},
    {"`world`", "world"},
    {"`world.bounds`", "world.bounds"},
    {"`world.obstacles[i]` (box)", "world.obstacles[0]"},
    {"`world.obstacles[i]` (cylinder)", "world.obstacles[1]"},
    {"`world.obstacles[i]` (sphere)", "world.obstacles[2]"},
    {"`world.moving_obstacles[i]` (cylinder)", "world.moving_obstacles[0]"},
    {"`world.moving_obstacles[i]` (box)", "world.moving_obstacles[1]"},
    {"`world.grid_map`", "world.grid_map"},
    {"`vehicles[i]`", "vehicles[0]"},
    {"`vehicles[i].reference`", "vehicles[0].reference"},
    {"`vehicles[i].battery`", "vehicles[0].battery"},
    {"`controller`", "controller"},
    {"`aerial`", "aerial"},
    {"`sim`", "sim"},
    {"`disturbances`", "disturbances"},
    {"`sensors`", "sensors"},
    {"`sensors.imu`", "sensors.imu"},
    {"`sensors.position`", "sensors.position"},
    {"`sensors.attitude`", "sensors.attitude"},
    {"`estimator`", "estimator"},
    {"`model_error`", "model_error"},
    {"`render`", "render"},
    {"`render.fixed_camera`", "render.fixed_camera"},
};

std::set<std::string> splitList(const std::string& list) {
  std::set<std::string> names;
  std::stringstream in(list);
  for (std::string name; std::getline(in, name, ',');) {
    name.erase(0, name.find_first_not_of(' '));
    names.insert(name);
  }
  return names;
}

// The names in "... (allowed: a, b, c)" at the end of a message.
std::set<std::string> allowedIn(const std::string& message) {
  const auto at = message.find("allowed: ");
  if (at == std::string::npos) return {};
  const auto end = message.find(')', at);
  return splitList(message.substr(at + 9, end - at - 9));
}

// The keys the loader accepts under `path`: it is asked to take a key it cannot know.
std::set<std::string> loaderKeys(const std::string& path) {
  const std::string probe = (path.empty() ? "" : path + ".") + "zzz_probe=1";
  try {
    parseScenario(kScenario, "probe.yaml", {probe});
  } catch (const InputError& e) {
    EXPECT_NE(e.problem().find("unknown key 'zzz_probe'"), std::string::npos) << e.what();
    return allowedIn(e.problem());
  }
  ADD_FAILURE() << "the loader accepted " << probe;
  return {};
}

// The trajectory parameters a flight of `mode` reads, asked of the built program the same way.
std::set<std::string> trajectoryKeys(const std::string& mode) {
  const fs::path dir = freshDir("readme-keys-" + mode);
  fs::create_directories(dir);
  const std::string scenario =
      "world: {bounds: {min: [0, 0, 0], max: [6, 6, 3]}}\n"
      "vehicles: [{name: uav1, model: cf2, start: [1, 1, 1], goal: [5, 5, 1]}]\n"
      "planner: {name: astar, resolution: 0.5}\n";
  std::ofstream(dir / "s.yaml") << scenario;
  const CommandResult r = runCosim(
      "run " + (dir / "s.yaml").string() + " --no-video --no-images --quiet --out " +
      (dir / "out").string() + " --set trajectory.mode=" + mode + " --set trajectory.zzz_probe=1");
  fs::remove_all(dir);
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("unknown parameter 'zzz_probe' for trajectory mode '" + mode + "'"),
            std::string::npos)
      << r.err;
  std::set<std::string> keys = allowedIn(r.err);
  keys.insert("mode");  // the section's own key, read by the loader
  return keys;
}

// The reference's "Every key" table (from its heading to the next heading): row label -> the
// backquoted names of its second column.
std::map<std::string, std::set<std::string>> keyReferenceTable() {
  const std::string doc = slurp(fs::path(COSIM_SOURCE_DIR) / kKeyReference);
  const auto start = doc.find("\n## Every key\n");
  EXPECT_NE(start, std::string::npos) << kKeyReference << " has no '## Every key' table";
  if (start == std::string::npos) return {};
  const std::string section = doc.substr(start, doc.find("\n#", start + 4) - start);
  std::map<std::string, std::set<std::string>> table;
  std::stringstream lines(section);
  const std::regex quoted("`([^`]+)`");
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("| ", 0) != 0 || line.rfind("| section", 0) == 0) continue;
    const auto second = line.find(" | ", 2);
    const auto third = line.find(" | ", second + 3);
    if (second == std::string::npos || third == std::string::npos) continue;
    const std::string keys = line.substr(second + 3, third - second - 3);
    std::set<std::string>& names = table[line.substr(2, second - 2)];
    for (std::sregex_iterator m(keys.begin(), keys.end(), quoted), end; m != end; ++m)
      names.insert((*m)[1]);
  }
  return table;
}

TEST(ReadmeScenarioKeys, EverySectionListsExactlyTheKeysTheLoaderAccepts) {
  const auto table = keyReferenceTable();
  for (const auto& [label, path] : kLoaderSections) {
    const auto row = table.find(label);
    ASSERT_NE(row, table.end()) << kKeyReference << "'s key table has no row " << label;
    const std::set<std::string> accepted = loaderKeys(path);
    EXPECT_FALSE(accepted.empty()) << label;
    EXPECT_EQ(row->second, accepted)
        << kKeyReference << " row " << label << " differs from the loader";
  }
}

TEST(ReadmeScenarioKeys, EveryTopLevelSectionHasARow) {
  const auto table = keyReferenceTable();
  for (const std::string& key : loaderKeys("")) {
    const bool has_row = std::any_of(table.begin(), table.end(), [&key](const auto& row) {
      return row.first.rfind("`" + key + "`", 0) == 0 || row.first.rfind("`" + key + ".", 0) == 0 ||
             row.first.rfind("`" + key + "[", 0) == 0;
    });
    EXPECT_TRUE(has_row) << kKeyReference << "'s key table has no row for section " << key;
  }
}

TEST(ReadmeScenarioKeys, TrajectoryRowsListTheParametersTheFlightReads) {
  const auto table = keyReferenceTable();
  for (const std::string mode : {"minimum_snap", "waypoints"}) {
    const auto row = table.find("`trajectory` (" + mode + ")");
    ASSERT_NE(row, table.end()) << kKeyReference << "'s key table has no row for trajectory "
                                << mode;
    EXPECT_EQ(row->second, trajectoryKeys(mode)) << mode;
  }
}

const char* const kTablesBegin = "<!-- declared keys: begin -->\n";
const char* const kTablesEnd = "<!-- declared keys: end -->\n";

TEST(ReadmeScenarioKeys, KeyByKeyTablesAreTheDeclarations) {
  const fs::path file = fs::path(COSIM_SOURCE_DIR) / kKeyReference;
  std::string doc = slurp(file);
  const auto begin = doc.find(kTablesBegin);
  const auto end = doc.find(kTablesEnd);
  ASSERT_NE(begin, std::string::npos) << kKeyReference << " has no " << kTablesBegin;
  ASSERT_NE(end, std::string::npos) << kKeyReference << " has no " << kTablesEnd;
  const auto from = begin + std::string(kTablesBegin).size();
  const std::string expected = declaredKeysMarkdown();
  if (std::getenv("COSIM_UPDATE_KEY_DOCS")) {
    doc.replace(from, end - from, expected);
    std::ofstream(file, std::ios::binary) << doc;
  }
  EXPECT_EQ(doc.substr(from, end - from), expected)
      << kKeyReference << "'s key-by-key tables differ from the declarations (rewrite them: "
      << "COSIM_UPDATE_KEY_DOCS=1 ctest -R ReadmeScenarioKeys)";
}

// The tables name real values: the sim section's row for timestep gives the default a scenario
// without the key runs with, and the range the loader enforces.
TEST(ReadmeScenarioKeys, TablesShowTheLoadersDefaultsAndRanges) {
  const std::string tables = declaredKeysMarkdown();
  EXPECT_NE(tables.find("| `timestep` | number | 0.001 | [1e-05, 0.02] |"), std::string::npos)
      << tables;
  const Scenario s = parseScenario(kScenario, "probe.yaml");
  EXPECT_EQ(s.sim.timestep, 0.001);
  try {
    parseScenario(kScenario, "probe.yaml", {"sim.timestep=0.03"});
    ADD_FAILURE() << "sim.timestep=0.03 accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.problem(), "= 0.03 is outside [1e-05, 0.02]");
  }
}

}  // namespace
}  // namespace cosim::test
