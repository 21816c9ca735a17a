// The lines of the frame's state box, for one vehicle, a few, and a mixed team.
#include "render/state_box_lines.h"

#include <gtest/gtest.h>

using namespace cosim;

namespace {

std::vector<StateBoxVehicle> mixedTeam() {
  std::vector<StateBoxVehicle> v;
  for (int i = 0; i < 8; ++i) {
    StateBoxVehicle r;
    r.name = "r";  // appended: GCC 12's -Wrestrict misfires on "r" + std::to_string
    r.name += std::to_string(i);
    r.kind = VehicleKind::GroundRobot;
    r.speed = 0.4;
    r.error = i == 5 ? 0.052 : 0.01;
    r.reference = ErrorReference::TimedPlan;
    r.at_goal = i < 3;
    v.push_back(r);
  }
  for (const char* name : {"uav1", "uav2"}) {
    StateBoxVehicle q;
    q.name = name;
    q.speed = 1.42;
    q.error = 0.0006;
    v.push_back(q);
  }
  return v;
}

const std::vector<StateLine> kMixedPlanners = {{"robot planner", "cbs"},
                                               {"quadrotor planner", "theta_star"}};

}  // namespace

TEST(StateBoxLines, SingleVehicleShowsSpeedAndErrorNamedByItsReference) {
  StateBoxVehicle v;
  v.name = "uav1";
  v.speed = 2.345;
  v.error = 0.0114;
  const auto lines = stateBoxLines(33.94, {v}, {{"planner", "theta_star"}}, 12);
  const std::vector<StateLine> expected = {{"time", "33.94 s"},
                                           {"speed", "2.35 m/s"},
                                           {"error to reference", "0.011 m"},
                                           {"planner", "theta_star"}};
  EXPECT_EQ(lines, expected);
}

TEST(StateBoxLines, MixedTeamListsTheQuadrotorsAndSummarisesTheRobots) {
  const auto lines = stateBoxLines(12.0, mixedTeam(), kMixedPlanners, 14);
  const std::vector<StateLine> expected = {
      {"time", "12.00 s"},           {"vehicle", "speed, error"},
      {"uav1", "1.42 m/s, 0.001 m"}, {"uav2", "1.42 m/s, 0.001 m"},
      {"robots at goal", "3 / 8"},   {"worst robot error", "0.052 m (r5)"},
      {"robot planner", "cbs"},      {"quadrotor planner", "theta_star"}};
  EXPECT_EQ(lines, expected);
}

TEST(StateBoxLines, SmallFrameDropsTheHeadingAndJoinsThePlanners) {
  const auto lines = stateBoxLines(12.0, mixedTeam(), kMixedPlanners, 6);
  ASSERT_EQ(lines.size(), 6u);
  EXPECT_EQ(lines[1].first, "uav1");
  EXPECT_EQ(lines[5], StateLine("planners", "cbs / theta_star"));
}

TEST(StateBoxLines, FewRobotsAreListedOneLineEach) {
  auto team = mixedTeam();
  team.erase(team.begin() + 3, team.begin() + 8);  // r0, r1, r2, uav1, uav2
  const auto lines = stateBoxLines(1.0, team, {{"planner", "cbs"}}, 14);
  ASSERT_EQ(lines.size(), 8u);  // time, heading, 5 vehicles, planner
  EXPECT_EQ(lines[2], StateLine("r0", "0.40 m/s, 0.010 m"));
  EXPECT_EQ(lines[6].first, "uav2");
}

TEST(StateBoxLines, ManyQuadrotorsAreSummarisedWhenTheyDoNotFit) {
  std::vector<StateBoxVehicle> swarm;
  for (int i = 0; i < 12; ++i) {
    StateBoxVehicle q;
    q.name = "q";
    q.name += std::to_string(i);
    q.error = 0.001 * i;
    q.at_goal = i % 2 == 0;
    swarm.push_back(q);
  }
  const auto lines = stateBoxLines(5.0, swarm, {{"planner", "rrt_star"}}, 8);
  const std::vector<StateLine> expected = {{"time", "5.00 s"},
                                           {"quadrotors at goal", "6 / 12"},
                                           {"worst quadrotor error", "0.011 m (q11)"},
                                           {"planner", "rrt_star"}};
  EXPECT_EQ(lines, expected);
}
