#include "render/metric_groups.h"

#include <algorithm>
#include <array>
#include <cstdlib>

namespace cosim {

namespace {

// Groups in reading order; a key goes to the first rule (in kRuleOrder) whose word it contains.
enum Group { Outcome, Safety, Tracking, Planning, SetUp, Simulation, kGroups };
const std::array<const char*, kGroups> kTitles = {"Outcome",  "Safety", "Tracking",
                                                  "Planning", "Set-up", "Simulation"};

struct Rule {
  Group group;
  std::vector<const char*> words;
};

// Checked in this order: the set-up's exact names first (trajectory_mode is a choice, not a
// planning result), the simulation's machinery last.
const std::vector<Rule>& rules() {
  static const std::vector<Rule> r = {
      {SetUp,
       {"sensors", "estimator", "controller", "drag_compensation", "vehicle_radius", "seed",
        "trajectory_mode", "robot", "model"}},
      {Outcome,
       {"reached", "collisions", "status", "message", "end_reason", "fault", "success",
        "flight_time", "arriv", "makespan"}},
      {Safety, {"clearance", "contact", "separation", "downwash"}},
      {Tracking,
       {"error", "rmse", "flown", "speed_mps", "thrust", "saturat", "energy", "deviation"}},
      {Planning, {"plan", "trajectory", "inflation", "sum_of_costs"}},
  };
  return r;
}

bool exactSetUpName(const std::string& key) {
  for (const char* w : rules().front().words)
    if (key == w) return true;
  return false;
}

Group groupOf(const std::string& key) {
  if (exactSetUpName(key)) return SetUp;
  for (std::size_t i = 1; i < rules().size(); ++i)
    for (const char* w : rules()[i].words)
      if (key.find(w) != std::string::npos) return rules()[i].group;
  return Simulation;
}

// "planner_counters.expansions" -> "planner_counters"
std::string topKey(const std::string& key) {
  return key.substr(0, key.find_first_of(".["));
}

// "vehicles[3].rmse_m" -> vehicle 3, metric "rmse_m"; false for other keys.
bool vehicleKey(const std::string& key, std::size_t& vehicle, std::string& metric) {
  const std::string prefix = "vehicles[";
  if (key.compare(0, prefix.size(), prefix) != 0) return false;
  const std::size_t close = key.find("].", prefix.size());
  if (close == std::string::npos) return false;
  vehicle = std::strtoul(key.c_str() + prefix.size(), nullptr, 10);
  metric = key.substr(close + 2);
  return true;
}

}  // namespace

GroupedMetrics groupMetrics(const std::vector<MetricRow>& flat) {
  GroupedMetrics out;
  std::array<std::vector<MetricRow>, kGroups> rows;
  VehicleMetricTable& t = out.vehicles;
  for (const MetricRow& row : flat) {
    std::size_t vehicle = 0;
    std::string metric;
    if (vehicleKey(row.first, vehicle, metric)) {
      if (vehicle >= t.vehicles.size()) t.vehicles.resize(vehicle + 1);
      if (metric == "name") {
        t.vehicles[vehicle] = row.second;
        continue;
      }
      auto it = std::find(t.metrics.begin(), t.metrics.end(), metric);
      if (it == t.metrics.end()) {
        t.metrics.push_back(metric);
        t.cells.emplace_back();
        it = t.metrics.end() - 1;
      }
      std::vector<std::string>& cells = t.cells[static_cast<std::size_t>(it - t.metrics.begin())];
      if (vehicle >= cells.size()) cells.resize(vehicle + 1);
      cells[vehicle] = row.second;
      continue;
    }
    rows[groupOf(topKey(row.first))].push_back(row);
  }
  for (std::size_t v = 0; v < t.vehicles.size(); ++v)
    if (t.vehicles[v].empty()) t.vehicles[v] = "vehicle " + std::to_string(v);
  for (auto& cells : t.cells) cells.resize(t.vehicles.size());
  for (const char* key : {"reached_goal", "collisions", "flight_time_s", "rmse_m", "max_error_m",
                          "min_clearance_m", "planned_length_m", "planning_time_ms"})
    for (const MetricRow& row : flat)
      if (row.first == key) out.headline.push_back(row);
  for (int g = 0; g < kGroups; ++g)
    if (!rows[g].empty()) out.groups.push_back({kTitles[g], std::move(rows[g])});
  return out;
}

}  // namespace cosim
