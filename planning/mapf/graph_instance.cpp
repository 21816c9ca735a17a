#include "planning/mapf/graph_instance.h"

#include "core/input_error.h"

namespace cosim {

GraphInstance graphInstance(const MapfInstance& instance) {
  GraphInstance g{MapfGraph::fromGrid(instance.grid, instance.connectivity), {}, {}};
  for (int i = 0; i < instance.agentCount(); ++i) {
    const int s = g.graph.vertexOf(instance.starts[i]), t = g.graph.vertexOf(instance.goals[i]);
    if (s == MapfGraph::kNoVertex || t == MapfGraph::kNoVertex)
      throw InputError("", "agent " + std::to_string(i), "start or goal is blocked or off the map");
    g.starts.push_back(s);
    g.goals.push_back(t);
  }
  return g;
}

std::vector<MapfPath> pathsOfConfigurations(const MapfGraph& graph,
                                            const std::vector<std::vector<int>>& configurations,
                                            int agents) {
  std::vector<MapfPath> paths(agents);
  for (int i = 0; i < agents; ++i) {
    for (const auto& c : configurations) paths[i].push_back(graph.cellOf(c[i]));
    trimWaitsAtEnd(paths[i]);
  }
  return paths;
}

}  // namespace cosim
