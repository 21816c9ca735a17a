// SACO and SACOdm of seed 000 (Pěňčík 2014, after Porta García et al. 2009).
#include <gtest/gtest.h>

#include <cmath>

#include "planning/grid/astar.h"
#include "planning/grid/movingai.h"
#include "planning/swarm/saco.h"
#include "tests/planning/ant_planner_checks.h"

using namespace cosim;

namespace {

using test::antQuery;
using test::expectLegalCellPath;

SacoParams sacoParams(double beta, int gamma, bool rolling) {
  SacoParams p;
  p.beta = beta;
  p.gamma = gamma;
  p.rolling_memory = rolling;
  p.elitist_weight = 0.0;
  p.conditional_diagonal = false;
  return p;
}

}  // namespace

TEST(Saco, PathsOnRandom32AreValidAndNoShorterThanAStar) {
  const OccupancyGrid g = readMovingAIMap(COSIM_SOURCE_DIR "/experiments/maps/random-32-32-10.map");
  const auto scen =
      readMovingAIScenario(COSIM_SOURCE_DIR "/experiments/maps/random-32-32-10-random-1.scen");
  Saco sacodm;  // defaults: SACOdm, beta 1, rolling gamma 1, EAS weight 1, conditional diagonal
  for (std::size_t i = 0; i < 20; ++i) {
    const Cell s{scen[i].start_x, scen[i].start_y, 0}, t{scen[i].goal_x, scen[i].goal_y, 0};
    const GridPlanResult r = sacodm.solveGrid(antQuery(g, s, t, i + 1), StopToken::untimed());
    ASSERT_TRUE(r.success) << r.message;
    EXPECT_EQ(r.cells.front(), s);
    EXPECT_EQ(r.cells.back(), t);
    expectLegalCellPath(g, r.cells, true);
    EXPECT_NEAR(r.length, gridPathLength(r.cells), 1e-9);
    EXPECT_GE(r.length, planAStar(g, s, t).length - 1e-9);
  }
}

// Seed 000 Fig. 6.5: processing shortens a raw walk a lot (58,895 -> 258 -> 154 there).
TEST(Saco, CycleRemovalThenSmoothingShortenTheFirstWalk) {
  const OccupancyGrid g(50, 50);
  Saco saco(sacoParams(0.0, 0, false));
  const GridPlanResult r =
      saco.solveGrid(antQuery(g, {2, 2, 0}, {48, 48, 0}, 5), StopToken::untimed());
  ASSERT_TRUE(r.success);
  const double raw = r.counters.at("first_walk_raw_length");
  const double loop_free = r.counters.at("first_walk_loop_free_length");
  const double smoothed = r.counters.at("first_walk_smoothed_length");
  EXPECT_GT(raw, 3.0 * loop_free);  // an undirected random walk on 2,500 cells loops a lot
  EXPECT_GT(loop_free, smoothed);
  EXPECT_GE(smoothed, 46 * std::sqrt(2.0) - 1e-9);
}

// Seed 000 Table 6.8 / claim 7: the distance term (beta = 1) makes the ants walk far less.
TEST(Saco, DistanceTermCutsTheWalkingOnTheFreeScene) {
  const OccupancyGrid g(50, 50);
  double saco_steps = 0, sacodm_steps = 0;
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    Saco saco(sacoParams(0.0, 0, false)), sacodm(sacoParams(1.0, 0, false));
    saco_steps +=
        saco.solveGrid(antQuery(g, {2, 2, 0}, {48, 48, 0}, seed), StopToken::untimed())
            .counters.at("expansions");
    sacodm_steps +=
        sacodm.solveGrid(antQuery(g, {2, 2, 0}, {48, 48, 0}, seed), StopToken::untimed())
            .counters.at("expansions");
  }
  EXPECT_GT(saco_steps, 3.0 * sacodm_steps);
}

// Seed 000 §4.5.1 / Table 6.9: a rolling list of the last gamma cells keeps the ants from walking
// back and forth for the whole walk, where [12]'s memory of the first gamma cells lapses after
// gamma steps: the walks get much shorter.
TEST(Saco, RollingMemoryWalksLessThanFirstGammaMemory) {
  const OccupancyGrid g(30, 30);
  double first = 0, rolling = 0;
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    SacoParams p = sacoParams(0.0, 7, false);
    p.iterations = 2;
    Saco a(p);
    p.rolling_memory = true;
    Saco b(p);
    first += a.solveGrid(antQuery(g, {1, 1, 0}, {28, 25, 0}, seed), StopToken::untimed())
                 .counters.at("expansions");
    rolling += b.solveGrid(antQuery(g, {1, 1, 0}, {28, 25, 0}, seed), StopToken::untimed())
                   .counters.at("expansions");
  }
  EXPECT_LT(rolling, 0.7 * first);
}

TEST(Saco, SameSeedSamePath) {
  const OccupancyGrid g = readMovingAIMap(COSIM_SOURCE_DIR "/experiments/maps/random-32-32-10.map");
  Saco a, b;
  const GridPlanResult ra =
      a.solveGrid(antQuery(g, {1, 1, 0}, {30, 28, 0}, 11), StopToken::untimed());
  const GridPlanResult rb =
      b.solveGrid(antQuery(g, {1, 1, 0}, {30, 28, 0}, 11), StopToken::untimed());
  ASSERT_TRUE(ra.success);
  EXPECT_TRUE(ra.cells == rb.cells);
}

TEST(Saco, UnreachableGoalIsReportedWithoutWalking) {
  OccupancyGrid g(30, 30);
  for (int y = 0; y < 30; ++y) g.setBlocked(15, y, 0, true);
  Saco saco;
  const GridPlanResult r =
      saco.solveGrid(antQuery(g, {2, 2, 0}, {28, 28, 0}, 1), StopToken::untimed());
  EXPECT_FALSE(r.success);
  EXPECT_NE(r.message.find("not reachable"), std::string::npos);
}

TEST(Saco, ElitistDepositSettlesTheColonyOnOnePath) {
  // With a strong elitist weight all ants soon walk the best-so-far path and the colony stops
  // early ("all ants found the same solution", seed §2.6 step 7).
  const OccupancyGrid g(12, 12);
  SacoParams p = sacoParams(1.0, 1, true);
  p.elitist_weight = 1000.0;
  p.iterations = 200;
  Saco saco(p);
  const GridPlanResult r =
      saco.solveGrid(antQuery(g, {0, 0, 0}, {11, 6, 0}, 2), StopToken::untimed());
  ASSERT_TRUE(r.success);
  EXPECT_LT(r.counters.at("iterations"), 200);
}
