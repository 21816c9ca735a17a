// seed004-mapf-scaling runs one instance per scenario file: several per map and size (the bundled
// -random-1..5 files), WHCA* beside LRA*, the method the thesis sets it against.
#include <gtest/gtest.h>

#include <map>
#include <nlohmann/json.hpp>
#include <string>

#include "experiments/reproduce/reproduction.h"

namespace cosim::reproduce {
Report seed004MapfScaling(const Options& options);

namespace {

TEST(Seed004MapfScaling, EveryCellHoldsOneInstancePerScenarioFile) {
  Options o;
  o.quick = true;
  o.runs = 3;  // scenario files -random-1..3
  const Report r = seed004MapfScaling(o);
  std::map<std::string, int> planners;
  ASSERT_FALSE(r.rows.empty());
  for (const JsonObject& row : r.rows) {
    const auto& j = row.json();
    EXPECT_EQ(j.at("instances").get<int>(), 3) << row.str();
    ++planners[j.at("planner").get<std::string>()];
  }
  EXPECT_EQ(planners, (std::map<std::string, int>{{"cbs", 6}, {"lra_star", 6}, {"whca_star", 6}}));
  EXPECT_NE(r.markdown.find("3 files per map (-random-1..3)"), std::string::npos);
}

}  // namespace
}  // namespace cosim::reproduce
