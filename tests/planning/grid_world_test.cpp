// The grid planners as registered planners (through GridWorldPlanner).
#include <gtest/gtest.h>

#include "core/input_error.h"
#include "planning/planner_registry.h"

using namespace cosim;

TEST(GridWorldPlanning, AllFiveGridPlannersAreRegisteredByTheirContractNames) {
  for (const char* name : {"dijkstra", "bellman_ford", "astar", "theta_star", "lazy_theta_star"}) {
    const PlannerEntry* e = PlannerRegistry::instance().find(name);
    ASSERT_NE(e, nullptr) << name;
    EXPECT_EQ(e->family, "grid");
    EXPECT_TRUE(e->make_grid) << name;
    ParamSet p("test");
    EXPECT_EQ(makeGridPlanner(name, p)->name(), name);
  }
}

TEST(GridWorldPlanning, InvalidConnectivityOrUnknownParameterIsAnInputError) {
  ParamSet bad("scenario.yaml");
  bad.set("connectivity", "5", "line 9");
  EXPECT_THROW(makeGridPlanner("astar", bad), InputError);
  ParamSet typo("scenario.yaml");
  typo.set("corner_cuting", "true", "line 9");
  EXPECT_THROW(makeGridPlanner("theta_star", typo), InputError);
}
