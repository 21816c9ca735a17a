#include "planning/mapf/mapf_problem.h"

#include <algorithm>
#include <set>
#include <tuple>
#include <utility>

#include "core/input_error.h"

namespace cosim {

int arrivalTime(const MapfPath& path) {
  if (path.empty()) return 0;
  int t = static_cast<int>(path.size()) - 1;
  while (t > 0 && path[t - 1] == path.back()) --t;
  return t;
}

long sumOfCosts(const std::vector<MapfPath>& paths) {
  long total = 0;
  for (const auto& p : paths) total += arrivalTime(p);
  return total;
}

int makespan(const std::vector<MapfPath>& paths) {
  int m = 0;
  for (const auto& p : paths) m = std::max(m, arrivalTime(p));
  return m;
}

void trimWaitsAtEnd(MapfPath& path) {
  path.resize(static_cast<std::size_t>(arrivalTime(path)) + 1);
}

void checkMapfInstance(const MapfInstance& instance, const std::string& file) {
  const int c = instance.connectivity;
  if (instance.grid.is3D() && c != 6 && c != 18 && c != 26)
    throw InputError(file, "connectivity", "must be 6, 18 or 26 on a 3D grid");
  if (!instance.grid.is3D() && c != 4 && c != 8)
    throw InputError(file, "connectivity", "must be 4 or 8");
  if (instance.starts.size() != instance.goals.size())
    throw InputError(file, "agents", "as many goals as starts are needed");
  const long cells =
      static_cast<long>(instance.grid.nx()) * instance.grid.ny() * instance.grid.nz();
  if (cells > kMaxMapfCells)
    throw InputError(file, "map",
                     "a " + std::to_string(instance.grid.nx()) + "x" +
                         std::to_string(instance.grid.ny()) + " map has more than the " +
                         std::to_string(kMaxMapfCells) + " cells multi-agent planning allows");
  if (instance.agentCount() > kMaxMapfAgents)
    throw InputError(file, "agents",
                     std::to_string(instance.agentCount()) + " agents, more than the " +
                         std::to_string(kMaxMapfAgents) + " allowed");
  std::set<std::tuple<int, int, int>> starts, goals;
  for (int i = 0; i < instance.agentCount(); ++i) {
    const std::string where = "agent " + std::to_string(i);
    const Cell& s = instance.starts[i];
    const Cell& g = instance.goals[i];
    if (instance.grid.blocked(s)) throw InputError(file, where, "start is blocked or off the map");
    if (instance.grid.blocked(g)) throw InputError(file, where, "goal is blocked or off the map");
    if (!starts.insert({s.x, s.y, s.z}).second)
      throw InputError(file, where, "start is shared with an earlier agent");
    if (!goals.insert({g.x, g.y, g.z}).second)
      throw InputError(file, where, "goal is shared with an earlier agent (Szulc 2018 §1.2)");
  }
}

}  // namespace cosim
