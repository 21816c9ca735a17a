#include "experiments/reproduce/seed004_figures.h"

#include <map>

#include "experiments/reproduce/reproduction_map.h"

namespace cosim::reproduce {

std::string drawMapfInstance(const std::string& out_dir, const std::string& name, int index,
                             const std::string& title, const MapfInstance& instance,
                             const std::vector<std::pair<std::string, const MapfTrial*>>& trials) {
  ReproductionMap fig =
      gridMap(title, instance.grid, instance.starts.front(), instance.goals.front());
  for (std::size_t a = 1; a < instance.starts.size(); ++a) {
    fig.more_starts.emplace_back(instance.starts[a].x + 0.5, instance.starts[a].y + 0.5);
    fig.more_goals.emplace_back(instance.goals[a].x + 0.5, instance.goals[a].y + 0.5);
  }
  for (const auto& [label, trial] : trials)
    for (std::size_t a = 0; a < trial->paths.size(); ++a)
      fig.paths.push_back(
          {label + ", robot " + std::to_string(a + 1), cellCentres(trial->paths[a])});
  return writeReproductionMap(out_dir, name, index, fig);
}

double doorCrossingShare(const MapfInstance& instance) {
  const int wall = instance.grid.nx() / 2;
  int crossing = 0;
  for (int a = 0; a < instance.agentCount(); ++a)
    crossing += (instance.starts[a].x < wall) != (instance.goals[a].x < wall);
  return instance.agentCount() ? static_cast<double>(crossing) / instance.agentCount() : 0.0;
}

std::string failureCauses(const std::vector<MapfTrial>& trials) {
  std::map<std::string, int> causes;
  for (const MapfTrial& t : trials) {
    if (t.solved) continue;
    const std::string& m = t.message;
    const char* cause = m.find("time limit") != std::string::npos ? "time limit"
                        : m.find("steps") != std::string::npos    ? "step limit"
                        : m.find("no route") != std::string::npos ? "no route in window"
                                                                  : "other";
    ++causes[cause];
  }
  std::string s;
  for (const auto& [cause, n] : causes)
    s += (s.empty() ? "" : ", ") + cause + " " + std::to_string(n);
  return s.empty() ? "none" : s;
}

}  // namespace cosim::reproduce
