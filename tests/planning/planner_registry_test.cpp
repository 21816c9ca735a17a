#include "planning/planner_registry.h"

#include <gtest/gtest.h>

#include "core/input_error.h"

using namespace cosim;

TEST(PlannerRegistry, ParameterOfAnotherPlannerIsReportedWhenTheCallerCollectsThem) {
  // plan-bench gives every planner it compares the scenario's parameters: a grid's
  // `resolution` given to rrt_star is collected, not an error.
  ParamSet params("s.yaml");
  params.set("resolution", "0.5", "line 3, key planner.resolution");
  params.set("step", "2", "line 3, key planner.step");
  std::vector<std::string> ignored;
  auto planner = makePlanner("rrt_star", params, "key planner.name", &ignored);
  ASSERT_NE(planner, nullptr);
  ASSERT_EQ(ignored.size(), 1u);
  EXPECT_EQ(ignored[0], "resolution");
}

TEST(PlannerRegistry, ParameterOfAnotherPlannerIsAnErrorNamingWhoTakesItAndWhatThisOneTakes) {
  // `--set planner.step=1` with theta_star: step is rrt's and others', never theta_star's.
  ParamSet params("s.yaml");
  params.set("resolution", "0.5", "line 3, key planner.resolution");
  params.set("step", "1", "command line, --set planner.step");
  try {
    makePlanner("theta_star", params);
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.place(), "command line, --set planner.step");
    const std::string problem = e.problem();
    EXPECT_NE(problem.find("parameter 'step' does not apply to planner 'theta_star'"),
              std::string::npos)
        << problem;
    EXPECT_NE(problem.find("rrt_star"), std::string::npos) << problem;
    EXPECT_NE(problem.find("theta_star' takes: "), std::string::npos) << problem;
    EXPECT_NE(problem.find("resolution"), std::string::npos) << problem;
    EXPECT_EQ(problem.find('\n'), std::string::npos) << problem;
  }
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
  for (const char* name : {"dijkstra",
                           "bellman_ford",
                           "astar",
                           "theta_star",
                           "lazy_theta_star",
                           "prm",
                           "rrt",
                           "rrt_star",
                           "rrt_star_fn",
                           "rrt_connect",
                           "informed_rrt_star",
                           "msac",
                           "saco",
                           "sacodm",
                           "ant_grid",
                           "acs_maklink",
                           "mmas",
                           "pso",
                           "ga",
                           "rna",
                           "wf_rna",
                           "d_star_lite"})
    EXPECT_NE(PlannerRegistry::instance().find(name), nullptr) << name;
}
