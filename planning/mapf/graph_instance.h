#pragma once
// A MapfInstance as the graph search sees it: its grid as a MapfGraph, starts and goals as
// vertices; and a solution back as grid paths (MapfPath: cells from t = 0 to the arrival).
#include <vector>

#include "planning/mapf/mapf_graph.h"
#include "planning/mapf/mapf_problem.h"

namespace cosim {

struct GraphInstance {
  MapfGraph graph;
  std::vector<int> starts, goals;
};

// Throws InputError for a connectivity the grid does not have (see MapfGraph::fromGrid) or a
// start or goal that is not a free cell.
GraphInstance graphInstance(const MapfInstance& instance);

// configurations[t][i]: agent i's vertex at time t. Each path ends at the agent's arrival.
std::vector<MapfPath> pathsOfConfigurations(const MapfGraph& graph,
                                            const std::vector<std::vector<int>>& configurations,
                                            int agents);

}  // namespace cosim
