#pragma once
// A run's metrics (flattened metrics.json) sorted into the groups a reader looks for: the
// outcome first, then safety, tracking, planning, the set-up, and the machinery last; every
// vehicle's own metrics as one table with a column per vehicle. Keys keep the order of
// metrics.json within a group.
#include <string>
#include <utility>
#include <vector>

namespace cosim {

using MetricRow = std::pair<std::string, std::string>;

struct MetricGroup {
  std::string title;
  std::vector<MetricRow> rows;
};

// Per-vehicle metrics (keys "vehicles[i].name"): metric names down, vehicles across.
struct VehicleMetricTable {
  std::vector<std::string> vehicles;            // column titles (the vehicles' names)
  std::vector<std::string> metrics;             // row titles
  std::vector<std::vector<std::string>> cells;  // [metric][vehicle], empty where absent
};

struct GroupedMetrics {
  std::vector<MetricRow> headline;  // the few figures a reader wants first
  std::vector<MetricGroup> groups;  // non-empty groups, in reading order
  VehicleMetricTable vehicles;      // empty when metrics.json has no vehicles list
};

GroupedMetrics groupMetrics(const std::vector<MetricRow>& flat);

}  // namespace cosim
