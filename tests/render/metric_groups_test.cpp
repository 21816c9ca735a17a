// index.html's metric groups: each metric where a reader looks for it.
#include "render/metric_groups.h"

#include <gtest/gtest.h>

using namespace cosim;

namespace {
const MetricGroup* group(const GroupedMetrics& g, const std::string& title) {
  for (const auto& x : g.groups)
    if (x.title == title) return &x;
  return nullptr;
}
bool has(const MetricGroup* g, const std::string& key) {
  if (!g) return false;
  for (const auto& [k, v] : g->rows)
    if (k == key) return true;
  return false;
}
}  // namespace

TEST(MetricGroups, MetricsFallIntoTheirGroupsInReadingOrder) {
  const GroupedMetrics g = groupMetrics({{"reached_goal", "true"},
                                         {"planner", "theta_star"},
                                         {"rmse_m", "0.01"},
                                         {"min_clearance_m", "0.4"},
                                         {"trajectory_mode", "minimum_snap"},
                                         {"planner_counters.expansions", "120"},
                                         {"wall_time_s", "3"},
                                         {"collisions", "0"}});
  ASSERT_EQ(g.groups.size(), 6u);
  EXPECT_EQ(g.groups[0].title, "Outcome");
  EXPECT_TRUE(has(group(g, "Outcome"), "reached_goal"));
  EXPECT_TRUE(has(group(g, "Outcome"), "collisions"));
  EXPECT_TRUE(has(group(g, "Safety"), "min_clearance_m"));
  EXPECT_TRUE(has(group(g, "Tracking"), "rmse_m"));
  EXPECT_TRUE(has(group(g, "Planning"), "planner"));
  EXPECT_TRUE(has(group(g, "Planning"), "planner_counters.expansions"));
  EXPECT_TRUE(has(group(g, "Set-up"), "trajectory_mode"));
  EXPECT_TRUE(has(group(g, "Simulation"), "wall_time_s"));
  // The headline keeps its fixed order, whatever the file's.
  ASSERT_EQ(g.headline.size(), 4u);
  EXPECT_EQ(g.headline[0].first, "reached_goal");
  EXPECT_EQ(g.headline[1].first, "collisions");
  EXPECT_EQ(g.headline[2].first, "rmse_m");
}

TEST(MetricGroups, VehicleMetricsBecomeOneTableWithAColumnPerVehicle) {
  const GroupedMetrics g = groupMetrics({{"vehicles[0].name", "r1"},
                                         {"vehicles[0].rmse_m", "0.1"},
                                         {"vehicles[1].name", "r2"},
                                         {"vehicles[1].rmse_m", "0.2"},
                                         {"vehicles[1].arrival_s", "9"}});
  EXPECT_TRUE(g.groups.empty());
  EXPECT_EQ(g.vehicles.vehicles, (std::vector<std::string>{"r1", "r2"}));
  ASSERT_EQ(g.vehicles.metrics, (std::vector<std::string>{"rmse_m", "arrival_s"}));
  EXPECT_EQ(g.vehicles.cells[0], (std::vector<std::string>{"0.1", "0.2"}));
  EXPECT_EQ(g.vehicles.cells[1], (std::vector<std::string>{"", "9"}));
}
