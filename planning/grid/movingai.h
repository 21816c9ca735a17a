#pragma once
// Readers for the MovingAI benchmark formats (https://movingai.com/benchmarks/formats.html):
// `.map` grids and `.scen` scenario files. Both are strict: any malformation is an InputError
// naming the file and line.
#include <string>
#include <vector>

#include "planning/grid/occupancy_grid.h"

namespace cosim {

// '.', 'G', 'S' are passable; '@', 'O', 'T', 'W' blocked. Dimensions are checked against
// OccupancyGrid::kMaxCells before allocation.
OccupancyGrid readMovingAIMap(const std::string& path);
OccupancyGrid parseMovingAIMap(const std::string& text, const std::string& file_for_errors);

struct MovingAIScenarioLine {
  int line = 0;  // 1-based line number in the file
  int bucket = 0;
  std::string map;
  int width = 0, height = 0;
  int start_x = 0, start_y = 0, goal_x = 0, goal_y = 0;  // x = column, y = row
  double optimal_length = 0.0;
  // Digits after the decimal point in the file's optimal_length (8 in current files, 2 in the
  // older "version 1.0" files): a length agrees with it when it rounds to the printed value.
  int optimal_decimals = 0;
};

// True when `length` agrees with the line's optimal length: within 1e-4 relative, or within
// half a unit of the last printed decimal (the 2-decimal files round their lengths).
bool matchesOptimalLength(const MovingAIScenarioLine& line, double length);

// Accepts "version 1" (tab-separated) and the older "version 1.0" (space-separated).
std::vector<MovingAIScenarioLine> readMovingAIScenario(const std::string& path);
std::vector<MovingAIScenarioLine> parseMovingAIScenario(const std::string& text,
                                                        const std::string& file_for_errors);

}  // namespace cosim
