// What every `cosim reproduce` writes (docs/reproductions.md: NAME.md and NAME.json, a
// --quick run marked in both), and the rebuilt maps the seed-002 reproductions stand on: their
// structure is what makes the reproductions comparable with the seed, so it is pinned here.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "experiments/reproduce/report_files.h"
#include "experiments/reproduce/seed002_maklink_map.h"
#include "experiments/reproduce/seed002_workspaces.h"
#include "planning/grid/astar.h"
#include "tests/support/cosim_command.h"
#include "tests/support/json_fields.h"

namespace cosim::reproduce {
namespace {

Report twoRows() {
  Report r;
  r.markdown = "# Title\n\nBody.\n";
  JsonObject a, b;
  a.add("planner", "rrt").add("length_m", 12.5);
  b.add("planner", "rrt_star").add("length_m", 10.25);
  r.rows = {a, b};
  return r;
}

TEST(ReproductionFiles, QuickRunsAreMarkedUnderTheTitleAndInTheJson) {
  Options quick;
  quick.quick = true;
  const std::string md = reportMarkdown(quick, twoRows());
  EXPECT_EQ(md.rfind("# Title\n\n> **Quick run", 0), 0u) << md;
  EXPECT_NE(md.find("Body."), std::string::npos);
  const std::string json = reportJson("demo", quick, twoRows());
  EXPECT_TRUE(test::jsonTrue(json, "quick"));
  EXPECT_NE(json.find("\"experiment\": \"demo\""), std::string::npos);
  EXPECT_NE(json.find("\"planner\": \"rrt_star\""), std::string::npos);
  EXPECT_EQ(test::jsonNumber(json, "rows[0].length_m"), 12.5);
  Options full;
  EXPECT_EQ(reportMarkdown(full, twoRows()), twoRows().markdown);
  EXPECT_NE(reportJson("demo", full, twoRows()).find("\"quick\": false"), std::string::npos);
}

TEST(ReproductionFiles, TheCommandWritesBothFilesForAQuickRun) {
  const auto dir = test::freshDir("reproduce-files");
  const auto r = test::runCosim("reproduce seed003-discrete --quick --out " + dir.string());
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string json = test::slurp(dir / "seed003-discrete.json");
  const std::string md = test::slurp(dir / "seed003-discrete.md");
  EXPECT_TRUE(test::jsonTrue(json, "quick"));
  EXPECT_NE(json.find("\"planner\": \"lazy_theta_star\""), std::string::npos);
  EXPECT_NE(json.find("\"planner\": \"lazy_theta_star_requeue\""), std::string::npos);
  EXPECT_NE(json.find("\"map\": \"3d-3\""), std::string::npos);
  EXPECT_NE(md.find("Quick run"), std::string::npos);
  std::filesystem::remove_all(dir);
}

// Every thesis reproduction, in a --quick run, draws its rebuilt maps beside its report (PNG and
// SVG) and ends with the closing section, one verdict per thesis finding.
class ThesisReproduction : public ::testing::TestWithParam<const char*> {};

TEST_P(ThesisReproduction, QuickRunDrawsItsMapsAndEndsWithTheVerdicts) {
  const std::string name = GetParam();
  const auto dir = test::freshDir("reproduce-" + name);
  const auto r = test::runCosim("reproduce " + name + " --quick --out " + dir.string());
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string md = test::slurp(dir / (name + ".md"));
  EXPECT_GT(std::filesystem::file_size(dir / (name + "_map1.png")), 2000u);
  EXPECT_NE(test::slurp(dir / (name + "_map1.svg")).find("<svg"), std::string::npos);
  EXPECT_NE(md.find("](" + name + "_map1.png)"), std::string::npos) << md;
  const std::size_t closing = md.find("## Where we agree and where we differ");
  ASSERT_NE(closing, std::string::npos) << md;
  EXPECT_EQ(md.find("\n## ", closing + 1), std::string::npos) << "not the last section";
  const std::string tail = md.substr(closing);
  const auto count = [&](const std::string& what) {
    std::size_t n = 0;
    for (std::size_t at = tail.find(what); at != std::string::npos; at = tail.find(what, at + 1))
      ++n;
    return n;
  };
  EXPECT_GE(count("\n- "), 2u) << tail;
  EXPECT_EQ(count("\n- "), count("**agrees**") + count("**differs")) << tail;
  std::filesystem::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(All, ThesisReproduction,
                         ::testing::Values("seed000-msac", "seed000-sacodm", "seed000-rna",
                                           "seed002-maklink", "seed002-ant-vs-ga",
                                           "seed003-discrete", "seed003-sampling", "seed003-flight",
                                           "seed004-planners", "seed004-whca-window",
                                           "seed004-mapf-scaling"),
                         [](const ::testing::TestParamInfo<const char*>& info) {
                           std::string s = info.param;
                           std::replace(s.begin(), s.end(), '-', '_');
                           return s;
                         });

// Acceptance: the rebuilt workspaces 2 and 3 get harder as the seed's do (its
// first query: 610 -> 919 -> 914 cm), every optimum stays below the seed's ant length.
TEST(Seed002Workspaces, FirstQueryJumpsInWorkspacesTwoAndThreeAndOptimaStayBelowTheSeeds) {
  const auto ws = seed002Workspaces();
  ASSERT_EQ(ws.size(), 3u);
  double optimum[3][3];
  for (int w = 0; w < 3; ++w) {
    const OccupancyGrid g = seed002Grid(ws[w]);
    for (int q = 0; q < 3; ++q) {
      const Seed002Query& query = seed002Queries()[q];
      const GridPlanResult r = planAStar(g, query.start(), query.target());
      ASSERT_TRUE(r.success) << w << " " << q;
      optimum[w][q] = r.length * kSeed002CellCm;
      EXPECT_LT(optimum[w][q], kSeed002Length[w][q][0]) << w << " " << q;
      EXPECT_GT(optimum[w][q], 0.95 * kSeed002Length[w][q][0]) << w << " " << q;
    }
  }
  EXPECT_GE(optimum[1][0], 1.3 * optimum[0][0]);
  EXPECT_GE(optimum[2][0], 1.3 * optimum[0][0]);
  for (int q = 1; q < 3; ++q) EXPECT_LT(optimum[1][q], 1.15 * optimum[0][q]) << q;
}

TEST(Seed002MaklinkMap, HasTheSeedsLinesCrossingsAndDijkstraLength) {
  const Seed002MaklinkMap map = seed002MaklinkMap();
  EXPECT_EQ(map.graph.lines().size(), 26u);
  const MaklinkRoute route = map.graph.shortestRoute(map.start, map.goal);
  ASSERT_TRUE(route.found);
  EXPECT_EQ(route.lines.size(), 9u);
  EXPECT_NEAR(route.length, 507.692, 0.2);
}

}  // namespace
}  // namespace cosim::reproduce
