#pragma once
// A MAPF instance from MovingAI benchmark files (Stern et al., SoCS 2019): the map, and the first
// `agents` lines of a scenario as the agents' starts and goals (x = column, y = row).
#include <string>

#include "planning/mapf/mapf_problem.h"

namespace cosim {

// Throws InputError naming the file if it cannot be read, the scenario has fewer than `agents`
// lines, a line's map size differs from the map's, or starts/goals are blocked or shared.
MapfInstance readMovingAIMapfInstance(const std::string& map_path, const std::string& scen_path,
                                      int agents, int connectivity = 4);

}  // namespace cosim
