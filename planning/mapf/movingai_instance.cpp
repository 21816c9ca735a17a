#include "planning/mapf/movingai_instance.h"

#include "core/input_error.h"

namespace cosim {

MapfInstance readMovingAIMapfInstance(const std::string& map_path, const std::string& scen_path,
                                      int agents, int connectivity) {
  const OccupancyGrid map = readMovingAIMap(map_path);
  return mapfInstanceFromScenario(map, readMovingAIScenario(scen_path), agents, connectivity,
                                  map_path, scen_path);
}

MapfInstance mapfInstanceFromScenario(const OccupancyGrid& map,
                                      const std::vector<MovingAIScenarioLine>& lines, int agents,
                                      int connectivity, const std::string& map_path,
                                      const std::string& scen_path) {
  MapfInstance inst;
  inst.grid = map;
  inst.connectivity = connectivity;
  if (agents < 1) throw InputError("command line", "--agents", "must be at least 1");
  if (agents > static_cast<int>(lines.size()))
    throw InputError(scen_path, "",
                     "has " + std::to_string(lines.size()) + " scenario lines, fewer than the " +
                         std::to_string(agents) + " agents asked for");
  for (int i = 0; i < agents; ++i) {
    const auto& l = lines[i];
    if (l.width != inst.grid.nx() || l.height != inst.grid.ny())
      throw InputError(scen_path, "line " + std::to_string(l.line),
                       "map size " + std::to_string(l.width) + "x" + std::to_string(l.height) +
                           " differs from " + map_path);
    inst.starts.push_back({l.start_x, l.start_y, 0});
    inst.goals.push_back({l.goal_x, l.goal_y, 0});
  }
  checkMapfInstance(inst, scen_path);
  return inst;
}

}  // namespace cosim
