// `cosim plan` as a new user meets it: the path drawn in its world beside path.csv, a path that
// starts and ends at the scenario's own start and goal without a hook through grid-cell centres,
// and a parameter of another planner refused in one line instead of silently dropped.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <algorithm>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "tests/support/cosim_command.h"

namespace cosim::test {
namespace {

namespace fs = std::filesystem;

const std::string kDefault = std::string(COSIM_SOURCE_DIR) + "/experiments/scenarios/default.yaml";

std::vector<Eigen::Vector3d> readPath(const fs::path& csv) {
  std::istringstream in(slurp(csv));
  std::string line;
  std::getline(in, line);  // x,y,z
  std::vector<Eigen::Vector3d> points;
  while (std::getline(in, line)) {
    Eigen::Vector3d p;
    char comma = 0;
    std::istringstream row(line);
    row >> p.x() >> comma >> p.y() >> comma >> p.z();
    points.push_back(p);
  }
  return points;
}

TEST(PlanCommand, DrawsThePathInItsWorldFromAboveAndFromTheSide) {
  const fs::path out = freshDir("plan-picture");
  const CommandResult r = runCosim("plan " + kDefault + " --out " + out.string());
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string png = slurp(out / "plan.png");
  ASSERT_GT(png.size(), 8u);
  EXPECT_EQ(png.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
  const std::string svg = slurp(out / "plan.svg");
  EXPECT_NE(svg.find("from above"), std::string::npos);
  EXPECT_NE(svg.find("from the side"), std::string::npos);
  EXPECT_NE(r.out.find("picture: " + (out / "plan.png").string()), std::string::npos) << r.out;
  // Lengths to the centimetre, not std::to_string's six decimals.
  EXPECT_NE(r.out.find(" m, "), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("00000 m"), std::string::npos) << r.out;
  fs::remove_all(out);
}

TEST(PlanCommand, ThePathLeavesTheStartAndReachesTheGoalWithoutAHook) {
  const fs::path out = freshDir("plan-no-hooks");
  const CommandResult r = runCosim("plan " + kDefault + " --out " + out.string());
  ASSERT_EQ(r.status, 0) << r.err;
  const std::vector<Eigen::Vector3d> path = readPath(out / "path.csv");
  ASSERT_GE(path.size(), 3u);
  EXPECT_TRUE(path.front().isApprox(Eigen::Vector3d(2, 2, 2)));
  EXPECT_TRUE(path.back().isApprox(Eigen::Vector3d(36, 26, 3)));
  // The first and last legs are the path's own, not a step to a cell's centre (at most 0.43 m
  // on the 0.5 m grid) followed by a turn.
  EXPECT_GT((path[1] - path[0]).norm(), 0.5);
  EXPECT_GT((path.back() - path[path.size() - 2]).norm(), 0.5);
  fs::remove_all(out);
}

TEST(PlanCommand, AParameterOfAnotherPlannerIsRefusedNamingThePlannerAndItsParameters) {
  const fs::path out = freshDir("plan-foreign-parameter");
  const CommandResult r =
      runCosim("plan " + kDefault + " --set planner.step=1 --out " + out.string());
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("parameter 'step' does not apply to planner 'theta_star'"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("'theta_star' takes: "), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_FALSE(fs::exists(out / "path.csv"));
  fs::remove_all(out);
}

TEST(PlanCommand, AnotherPlannerChosenByOptionSetsTheFilesGridParametersAside) {
  // default.yaml is written for theta_star (resolution: 0.5); trying rrt_connect on it is what
  // --planner is for: the file's resolution is set aside with a note, not an error. The same
  // parameter given on the command line is the user's own and is refused.
  const fs::path out = freshDir("plan-other-planner");
  const CommandResult r =
      runCosim("plan " + kDefault + " --planner rrt_connect --out " + out.string());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("note: the scenario's planner.resolution does not apply to rrt_connect"),
            std::string::npos)
      << r.out;
  const CommandResult mine =
      runCosim("plan " + kDefault + " --planner rrt_connect --set planner.resolution=0.25 --out " +
               out.string());
  EXPECT_EQ(mine.status, 2);
  EXPECT_NE(mine.err.find("parameter 'resolution' does not apply to planner 'rrt_connect'"),
            std::string::npos)
      << mine.err;
  fs::remove_all(out);
}

}  // namespace
}  // namespace cosim::test
