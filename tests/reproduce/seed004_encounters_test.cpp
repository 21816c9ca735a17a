// What seed 004's reproductions measure about how robots met: two robots backing off at the same
// step (§6.1's "mutual retreat"), a failed run going round the same joint positions (a
// livelock), and the bottleneck with every robot forced through its door.
#include "experiments/reproduce/seed004_encounters.h"

#include <gtest/gtest.h>

#include "experiments/reproduce/seed004_environments.h"
#include "experiments/reproduce/seed004_figures.h"

namespace cosim::reproduce {
namespace {

MapfInstance openRoom(Cell a_start, Cell a_goal, Cell b_start, Cell b_goal) {
  MapfInstance inst;
  inst.grid = OccupancyGrid(10, 10);
  inst.connectivity = 4;
  inst.starts = {a_start, b_start};
  inst.goals = {a_goal, b_goal};
  return inst;
}

TEST(Seed004Encounters, CountsTwoNearbyRobotsSteppingAwayFromTheirGoalsTogether) {
  // Face to face in a row, each with its goal behind the other: both step back once, then pass.
  const MapfInstance inst = openRoom({4, 5, 0}, {8, 5, 0}, {5, 5, 0}, {1, 5, 0});
  MapfTrial both_back;
  both_back.paths = {{{4, 5, 0}, {3, 5, 0}, {3, 4, 0}}, {{5, 5, 0}, {6, 5, 0}, {6, 6, 0}}};
  EXPECT_EQ(mutualRetreatSteps(inst, both_back), 1);
  // One waits while the other backs off: no mutual retreat.
  MapfTrial one_waits;
  one_waits.paths = {{{4, 5, 0}, {4, 5, 0}, {4, 5, 0}}, {{5, 5, 0}, {6, 5, 0}, {6, 6, 0}}};
  EXPECT_EQ(mutualRetreatSteps(inst, one_waits), 0);
  // Far apart, both stepping away: not a meeting.
  const MapfInstance far = openRoom({0, 0, 0}, {0, 9, 0}, {9, 9, 0}, {9, 0, 0});
  MapfTrial apart;
  apart.paths = {{{0, 0, 0}, {1, 0, 0}}, {{9, 9, 0}, {8, 9, 0}}};
  EXPECT_EQ(mutualRetreatSteps(far, apart), 0);
}

TEST(Seed004Encounters, TellsACycleFromAStandstill) {
  MapfTrial cycle;  // two robots swapping back and forth between two cells each, 12 steps
  for (int t = 0; t < 12; ++t) {
    cycle.paths.resize(2);
    cycle.paths[0].push_back({t % 2, 0, 0});
    cycle.paths[1].push_back({5, t % 2, 0});
  }
  EXPECT_TRUE(cyclesThroughJointPositions(cycle));
  MapfTrial standstill;  // both wait where they are for 12 steps
  standstill.paths = {MapfPath(12, Cell{0, 0, 0}), MapfPath(12, Cell{5, 5, 0})};
  EXPECT_FALSE(cyclesThroughJointPositions(standstill));
  MapfTrial straight;  // one robot walks a line: no joint position repeats
  straight.paths = {{}, MapfPath(12, Cell{5, 5, 0})};
  for (int t = 0; t < 12; ++t) straight.paths[0].push_back({t, 0, 0});
  EXPECT_FALSE(cyclesThroughJointPositions(straight));
}

TEST(Seed004Encounters, ThroughTheDoorPlacesEveryStartLeftAndEveryGoalRightOfTheWall) {
  const OccupancyGrid grid = seed004Map(Seed004Environment::kBottleneck, 15, 15, 1);
  const MapfInstance inst = robotsThroughTheDoor(grid, 20, 7, 8);
  ASSERT_EQ(inst.agentCount(), 20);
  for (int a = 0; a < 20; ++a) {
    EXPECT_LT(inst.starts[a].x, 7);
    EXPECT_GT(inst.goals[a].x, 7);
  }
  EXPECT_DOUBLE_EQ(doorCrossingShare(inst), 1.0);
  // Random placement puts only some robots across (the share the planners report gives).
  EXPECT_LT(doorCrossingShare(randomlyPlacedRobots(grid, 20, 7, 8)), 0.9);
}

}  // namespace
}  // namespace cosim::reproduce
