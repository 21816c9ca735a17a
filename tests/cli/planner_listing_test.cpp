// What the program says about its planners: `cosim plan --list` shows each planner's parameters
// with the defaults the planners use, and plan.json / mapf.json say how the search ended
// ("status", beside every key they had).
#include <gtest/gtest.h>

#include <fstream>

#include "tests/support/cosim_command.h"

namespace cosim::test {
namespace {

namespace fs = std::filesystem;

// The lines of `text` from the one starting with `header` to the next empty line.
std::string block(const std::string& text, const std::string& header) {
  const auto from = text.find("\n" + header);
  if (from == std::string::npos) return "";
  const auto to = text.find("\n\n", from + 1);
  return text.substr(from + 1, to == std::string::npos ? std::string::npos : to - from - 1);
}

TEST(PlannerListing, ListsAstarWithItsResolutionDefaultAndCbsWithItsNodeBudget) {
  const CommandResult r = runCosim("plan --list");
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string astar = block(r.out, "astar  [grid]");
  ASSERT_FALSE(astar.empty()) << r.out;
  EXPECT_NE(astar.find("resolution       = 0.5 ([0.01, 100])"), std::string::npos) << astar;
  EXPECT_NE(astar.find("metres per grid cell"), std::string::npos) << astar;
  const std::string rrt_star = block(r.out, "rrt_star  [sampling]");
  EXPECT_NE(rrt_star.find("1: stop at the first path; 2: keep improving"), std::string::npos)
      << rrt_star;
  const std::string cbs = block(r.out, "cbs  [team]");
  EXPECT_NE(cbs.find("max_nodes      = 50000 (>= 1)"), std::string::npos) << cbs;
}

TEST(PlannerListing, PlanHelpPointsToTheList) {
  const CommandResult r = runCosim("plan --help");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("`cosim plan --list` lists every planner with its parameters"),
            std::string::npos)
      << r.out;
}

TEST(PlannerStatusKey, PlanJsonSaysExactSolutionBesideSuccess) {
  const fs::path dir = freshDir("plan-status");
  fs::create_directories(dir);
  std::ofstream(dir / "open.yaml")
      << "world: {bounds: {min: [0, 0, 0], max: [12, 8, 4]}}\n"
         "vehicles: [{name: uav1, model: cf2, start: [2, 2, 1], goal: [9, 6, 1]}]\n"
         "planner: {name: astar}\n";
  const CommandResult r =
      runCosim("plan " + (dir / "open.yaml").string() + " --out " + (dir / "plan").string());
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string json = slurp(dir / "plan" / "plan.json");
  EXPECT_NE(json.find("\"success\": true,\n  \"status\": \"exact_solution\""), std::string::npos)
      << json;
  EXPECT_NE(json.find("\"length_m\""), std::string::npos) << json;
  fs::remove_all(dir);
}

TEST(PlannerStatusKey, MapfJsonSaysWhyAPlannerFailed) {
  const fs::path dir = freshDir("mapf-status");
  const std::string data = COSIM_SOURCE_DIR "/experiments/maps/";
  // A CT-node budget of 1 with conflicting agents: the budget ends the search.
  const CommandResult r = runCosim("mapf " + data + "empty-8-8.map " + data +
                                   "empty-8-8-random-1.scen --agents 8 --planner cbs --set "
                                   "max_nodes=1 --out " +
                                   dir.string());
  const std::string json = slurp(dir / "mapf.json");
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_NE(json.find("\"status\": \"limit_reached\""), std::string::npos) << json;
  EXPECT_NE(json.find("\"message\": \"constraint-tree node limit (max_nodes) reached\""),
            std::string::npos)
      << json;
  fs::remove_all(dir);
}

}  // namespace
}  // namespace cosim::test
