#include "planning/planner_registry.h"

#include <gtest/gtest.h>

#include "core/input_error.h"

using namespace cosim;

TEST(PlannerRegistry, ParameterOfAnotherPlannerIsIgnoredAndReported) {
  // A sweep switching planner.name from a grid planner to rrt_star keeps `resolution`: that is
  // a note, not an error.
  ParamSet params("s.yaml");
  params.set("resolution", "0.5", "line 3, key planner.resolution");
  params.set("step", "2", "line 3, key planner.step");
  std::vector<std::string> ignored;
  auto planner = makePlanner("rrt_star", params, "key planner.name", &ignored);
  ASSERT_NE(planner, nullptr);
  ASSERT_EQ(ignored.size(), 1u);
  EXPECT_EQ(ignored[0], "resolution");
}

TEST(PlannerRegistry, MisspeltParameterIsAnErrorNamingItsPlace) {
  ParamSet params("s.yaml");
  params.set("resolutoin", "0.5", "line 3, key planner.resolutoin");
  try {
    makePlanner("astar", params);
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.place(), "line 3, key planner.resolutoin");
    EXPECT_NE(e.problem().find("unknown parameter 'resolutoin'"), std::string::npos);
  }
}

TEST(PlannerRegistry, EveryContractPlannerNameIsRegistered) {
  for (const char* name : {"dijkstra", "bellman_ford", "astar", "theta_star", "lazy_theta_star",
                           "prm", "rrt", "rrt_star", "rrt_star_fn", "rrt_connect",
                           "informed_rrt_star", "msac", "saco", "sacodm", "ant_grid",
                           "acs_maklink", "mmas", "pso", "ga", "rna", "wf_rna", "d_star_lite"})
    EXPECT_NE(PlannerRegistry::instance().find(name), nullptr) << name;
}
