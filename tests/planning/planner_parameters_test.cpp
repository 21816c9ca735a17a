// Every planner declares its parameters through the calls that read them (ParamSet records the
// default and range of each ask), so `cosim plan --list` shows the defaults the planners really
// use; and every declared parameter has a one-line description.
#include <gtest/gtest.h>

#include "planning/mapf/mapf_planner_registry.h"
#include "planning/planner_parameter_docs.h"
#include "planning/planner_registry.h"

using namespace cosim;

namespace {

const ParamDeclaration* findDeclaration(const std::vector<ParamDeclaration>& all,
                                        const std::string& name) {
  for (const ParamDeclaration& d : all)
    if (d.name == name) return &d;
  return nullptr;
}

TEST(PlannerParameters, AstarDeclaresItsResolutionWithTheDefaultItUses) {
  const PlannerEntry* astar = PlannerRegistry::instance().find("astar");
  ASSERT_NE(astar, nullptr);
  const std::vector<ParamDeclaration> declared = declaredParameters(*astar);
  const ParamDeclaration* resolution = findDeclaration(declared, "resolution");
  ASSERT_NE(resolution, nullptr);
  EXPECT_EQ(resolution->default_value, "0.5");
  EXPECT_EQ(resolution->range, "[0.01, 100]");
  EXPECT_EQ(resolution->type, "number");
  const ParamDeclaration* blocking = findDeclaration(declared, "cell_blocking");
  ASSERT_NE(blocking, nullptr);
  EXPECT_EQ(blocking->default_value, "exact");  // A* checks segments: exact occupancy
  EXPECT_EQ(blocking->range, "exact|cell|centre");
}

TEST(PlannerParameters, ARangeOpenAboveIsShownAsALowerBound) {
  for (const MapfPlannerEntry& e : mapfPlanners()) {
    if (e.name != "cbs") continue;
    const std::vector<ParamDeclaration> declared = declaredParameters(e);
    const ParamDeclaration* nodes = findDeclaration(declared, "max_nodes");
    ASSERT_NE(nodes, nullptr);
    EXPECT_EQ(nodes->default_value, "50000");
    EXPECT_EQ(nodes->range, ">= 1");
    return;
  }
  FAIL() << "cbs is not registered";
}

// The declared default of every parameter is the value in force when the planner is built with
// no parameters at all (what plan.json's params shows), and it has a description.
TEST(PlannerParameters, EveryDeclaredDefaultIsTheValueInForceAndIsDescribed) {
  int checked = 0;
  for (const PlannerEntry& e : PlannerRegistry::instance().entries()) {
    ParamSet params("test");
    e.make(params);
    for (const ParamDeclaration& d : params.declarations()) {
      EXPECT_EQ(params.effective().at(d.name), d.default_value) << e.name << "." << d.name;
      EXPECT_FALSE(plannerParameterDescription(e.name, d.name).empty())
          << e.name << "." << d.name << " has no description";
      ++checked;
    }
    EXPECT_EQ(params.declarations().size(), params.effective().size()) << e.name;
  }
  for (const MapfPlannerEntry& e : mapfPlanners()) {
    ParamSet params("test");
    e.make(params);
    for (const ParamDeclaration& d : params.declarations()) {
      EXPECT_EQ(params.effective().at(d.name), d.default_value) << e.name << "." << d.name;
      EXPECT_FALSE(plannerParameterDescription(e.name, d.name).empty())
          << e.name << "." << d.name << " has no description";
      ++checked;
    }
  }
  EXPECT_GT(checked, 200);  // 24 single-vehicle and 9 team planners, most with several
}

// A value set by the user does not change what is declared: the declaration is the planner's.
TEST(PlannerParameters, ASetValueLeavesTheDeclaredDefault) {
  ParamSet params("test");
  params.set("resolution", "0.25");
  PlannerRegistry::instance().find("astar")->make(params);
  EXPECT_EQ(params.effective().at("resolution"), "0.25");
  EXPECT_EQ(findDeclaration(params.declarations(), "resolution")->default_value, "0.5");
}

}  // namespace
