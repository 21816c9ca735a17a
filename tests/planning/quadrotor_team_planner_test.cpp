// A quadrotor team planned jointly: the grid's cells are sqrt(2) scaled separation ellipsoids,
// blocked where the inflated obstacles reach; starts and goals that the grid cannot hold are bad
// input; the plan brings every vehicle to its goal on one schedule, keeping the separation.
#include "planning/team/quadrotor_team_planner.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/input_error.h"
#include "planning/mapf/mapf_planner_registry.h"
#include "planning/team/team_grid.h"

using namespace cosim;
using Eigen::Vector3d;

namespace {

// A 6 m x 1.6 m x 3 m corridor: three lanes of the team's grid side by side, two layers.
World corridor() {
  World w;
  w.bounds_min = {0, 0, 0};
  w.bounds_max = {6, 1.6, 3};
  return w;
}

World roomWithPillar() {
  World w;
  w.bounds_min = {0, 0, 0};
  w.bounds_max = {6, 4, 3};
  Obstacle pillar;
  pillar.type = ObstacleType::Cylinder;
  pillar.pos = {3, 2, 1.5};
  pillar.radius = 0.3;
  pillar.height = 3;
  w.obstacles.push_back(pillar);
  return w;
}

const SeparationEllipsoid kCf2{0.24, 0.6};

TeamAgent agent(const Vector3d& start, const Vector3d& goal) {
  TeamAgent a;
  a.start = start;
  a.goal = goal;
  a.separation = kCf2;
  a.inflation = 0.15;
  a.clearance = 0.1;
  return a;
}

// Four cf2 swap the ends of the corridor, two by two, crossing from side to side.
TeamPlanningProblem crossing(const World& world) {
  TeamPlanningProblem p;
  p.world = &world;
  p.agents = {agent({0.8, 0.3, 1}, {5.2, 1.3, 1}), agent({0.8, 1.3, 1}, {5.2, 0.3, 1}),
              agent({5.2, 0.3, 1}, {0.8, 1.3, 1}), agent({5.2, 1.3, 1}, {0.8, 0.3, 1})};
  return p;
}

TeamPlan plan(const TeamPlanningProblem& p) {
  ParamSet params;
  auto lacam = makeMapfPlanner("lacam", params);
  return planQuadrotorTeam(p, *lacam);
}

}  // namespace

TEST(TeamGrid, CellsAreSqrt2SeparationsWideAndTallAndBlockedAroundInflatedObstacles) {
  const World w = roomWithPillar();
  const Vector3d pitch = std::sqrt(2.0) * Vector3d(0.24, 0.24, 0.6);
  const TeamGrid g = TeamGrid::over(w, pitch, 0.15);
  EXPECT_EQ(g.occupancy().nx(), 17);  // floor(6 / 0.339)
  EXPECT_EQ(g.occupancy().ny(), 11);
  EXPECT_EQ(g.occupancy().nz(), 3);  // floor(3 / 0.849)
  // The cell holding the pillar's axis is blocked, one 1.36 m away is free.
  const Cell at_pillar = g.cellOf({3, 2, 1.5});
  EXPECT_TRUE(g.occupancy().blocked(at_pillar));
  EXPECT_FALSE(g.occupancy().blocked(g.cellOf({1.8, 2, 1.5})));
  // The next cell: its centre, 0.34 m from the axis, clears the pillar by only 0.04 m.
  const Cell next{at_pillar.x + 1, at_pillar.y, at_pillar.z};
  EXPECT_NEAR((g.centre(next) - Vector3d(3, 2, 1.5)).norm(), pitch.x(), 1e-9);
  EXPECT_TRUE(g.occupancy().blocked(next));
  // Two cells on, 0.68 m from the axis: its cross reaches 0.17 m closer, 0.21 m from the
  // surface, more than the 0.15 m inflation plus half the sample spacing.
  EXPECT_FALSE(g.occupancy().blocked({at_pillar.x + 2, at_pillar.y, at_pillar.z}));
  // Centred in the bounds: the left margin equals the right one.
  const Vector3d first = g.centre({0, 0, 0});
  const Vector3d last = g.centre({16, 10, 2});
  EXPECT_NEAR(first.x() - 0.5 * pitch.x(), 6 - (last.x() + 0.5 * pitch.x()), 1e-9);
  EXPECT_NEAR(first.z() - 0.5 * pitch.z(), 3 - (last.z() + 0.5 * pitch.z()), 1e-9);
}

TEST(QuadrotorTeamPlanner, FourCrossingCf2ArriveOnOneScheduleOutsideEachOthersEllipsoids) {
  const World w = corridor();
  const TeamPlanningProblem p = crossing(w);
  const TeamPlan r = plan(p);
  ASSERT_TRUE(r.success) << r.message;
  ASSERT_EQ(r.trajectories.size(), 4u);
  double end = 0.0;
  for (const auto& t : r.trajectories) end = std::max(end, t.duration());
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_LT((r.trajectories[i].sample(end).position - p.agents[i].goal).norm(), 1e-6) << i;
    EXPECT_LT((r.trajectories[i].sample(0).position - p.agents[i].start).norm(), 1e-6) << i;
  }
  // Checked here every 5 ms, independently of the smoother's own 20 ms checks.
  double closest = 1e9;
  for (double t = 0; t <= end; t += 0.005)
    for (std::size_t i = 0; i < 4; ++i)
      for (std::size_t j = i + 1; j < 4; ++j)
        closest = std::min(closest, kCf2.distance(r.trajectories[i].sample(t).position,
                                                  r.trajectories[j].sample(t).position));
  EXPECT_GE(closest, 0.98 * p.min_separation);
  EXPECT_LT(closest, 2.5);  // closer than two cells (4.24): they pass each other (2.39 here)
  EXPECT_GE(r.counters.at("planned_min_separation"), p.min_separation);
  EXPECT_NEAR(r.counters.at("pitch_xy_m"), std::sqrt(2.0) * p.min_separation * 0.24, 1e-6);
  EXPECT_NEAR(r.counters.at("step_duration_s"),
              teamStepDuration(Vector3d(0, 0, std::sqrt(2.0) * p.min_separation * 0.6), p.max_speed,
                               p.max_acceleration),
              1e-5);
}

TEST(QuadrotorTeamPlanner, TheStepTimeKeepsARestToRestMoveWithinSpeedAndAcceleration) {
  // 1 m at 1 m/s: 35/16 s; at 0.1 m/s^2 the acceleration binds: sqrt(7.51 / 0.1) s.
  EXPECT_NEAR(teamStepDuration({0.5, 0.5, 1.0}, 1.0, 100.0), 35.0 / 16.0, 1e-12);
  EXPECT_NEAR(teamStepDuration({0.5, 0.5, 1.0}, 100.0, 0.1), std::sqrt(75.1), 1e-12);
}

TEST(QuadrotorTeamPlanner, StartsAndGoalsTheGridCannotHoldAreBadInputNamingTheVehicle) {
  World w = corridor();
  Obstacle box;
  box.pos = {3, 0.8, 1.5};
  box.size = {0.4, 0.4, 3};
  w.obstacles.push_back(box);
  TeamPlanningProblem p = crossing(w);
  p.agents[1].start = {0.85, 0.35, 1};  // in agent 0's start cell
  try {
    plan(p);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.place(), "vehicles[1].start");
  }
  p = crossing(w);
  p.agents[2].goal = {3.1, 0.8, 1};  // inside the box
  try {
    plan(p);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.place(), "vehicles[2].goal");
  }
}
