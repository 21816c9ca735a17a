#pragma once
// A MAPF instance from MovingAI benchmark files (Stern et al., SoCS 2019): the map, and the first
// `agents` lines of a scenario as the agents' starts and goals (x = column, y = row).
#include <string>
#include <vector>

#include "planning/grid/movingai.h"
#include "planning/mapf/mapf_problem.h"

namespace cosim {

// Throws InputError naming the file if it cannot be read, the scenario has fewer than `agents`
// lines, a line's map size differs from the map's, or starts/goals are blocked or shared.
MapfInstance readMovingAIMapfInstance(const std::string& map_path, const std::string& scen_path,
                                      int agents, int connectivity = 4);

// The same from a map and scenario already read (a benchmark takes many agent counts from one
// scenario file). `map_path` and `scen_path` name the files in messages.
MapfInstance mapfInstanceFromScenario(const OccupancyGrid& map,
                                      const std::vector<MovingAIScenarioLine>& lines, int agents,
                                      int connectivity, const std::string& map_path,
                                      const std::string& scen_path);

}  // namespace cosim
