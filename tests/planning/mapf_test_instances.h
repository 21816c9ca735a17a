#pragma once
// Small MAPF instances for the tests, drawn as text: '.' free, '@' blocked.
#include <string>
#include <vector>

#include "planning/grid/movingai.h"
#include "planning/mapf/mapf_problem.h"

namespace cosim::test {

inline OccupancyGrid gridFromRows(const std::vector<std::string>& rows) {
  std::string text = "type octile\nheight " + std::to_string(rows.size()) + "\nwidth " +
                     std::to_string(rows[0].size()) + "\nmap\n";
  for (const auto& r : rows) text += r + "\n";
  return parseMovingAIMap(text, "test map");
}

inline MapfInstance instanceFrom(const std::vector<std::string>& rows, std::vector<Cell> starts,
                                 std::vector<Cell> goals, int connectivity = 4) {
  MapfInstance inst;
  inst.grid = gridFromRows(rows);
  inst.connectivity = connectivity;
  inst.starts = std::move(starts);
  inst.goals = std::move(goals);
  return inst;
}

// Two agents swap the ends of a corridor with one side pocket: their straight paths meet in a
// swap conflict between t = 2 and 3. Optimal: agent 0 ducks into the pocket (detour 2) while
// agent 1 passes without waiting; sum of costs 5 + 7 = 12, makespan 7.
inline MapfInstance pocketCorridor() {
  return instanceFrom({"......", "@@.@@@"}, {{0, 0, 0}, {5, 0, 0}}, {{5, 0, 0}, {0, 0, 0}});
}

}  // namespace cosim::test
