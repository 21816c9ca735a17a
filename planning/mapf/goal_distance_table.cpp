#include "planning/mapf/goal_distance_table.h"

namespace cosim {

GoalDistanceTable::GoalDistanceTable(const MapfGraph& graph, std::span<const int> goals,
                                     const Deadline& deadline)
    : vertices_(static_cast<std::size_t>(graph.vertexCount())),
      // A distance is below the vertex count, so 16 bits hold it with 0xffff left for
      // "unreachable".
      narrow_(graph.vertexCount() < kNarrowUnreachable) {
  complete_ = narrow_ ? fill(narrow_distances_, graph, goals, deadline, kNarrowUnreachable)
                      : fill(wide_distances_, graph, goals, deadline, kUnreachable);
}

template <typename T>
bool GoalDistanceTable::fill(std::vector<T>& distances, const MapfGraph& graph,
                             std::span<const int> goals, const Deadline& deadline, T unreachable) {
  distances.assign(goals.size() * vertices_, unreachable);
  std::vector<int> queue(vertices_);
  for (std::size_t a = 0; a < goals.size(); ++a) {
    if (deadline.expired()) return false;
    T* d = distances.data() + a * vertices_;
    std::size_t head = 0, tail = 0;
    d[goals[a]] = 0;
    queue[tail++] = goals[a];
    while (head < tail) {
      const int v = queue[head++];
      const T next = static_cast<T>(d[v] + 1);
      for (const int u : graph.neighbours(v))
        if (d[u] == unreachable) d[u] = next, queue[tail++] = u;
    }
  }
  return true;
}

}  // namespace cosim
