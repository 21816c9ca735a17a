#include "planning/mapf/goal_distance_table.h"

#include <algorithm>
#include <atomic>
#include <new>
#include <thread>
#include <unordered_map>

namespace cosim {

namespace {

template <typename T>
T* zeroed(std::size_t n) {
  void* p = std::calloc(n == 0 ? 1 : n, sizeof(T));
  if (p == nullptr) throw std::bad_alloc();
  return static_cast<T*>(p);
}

}  // namespace

// One breadth-first pass over the whole graph (a few milliseconds on the largest benchmark map).
bool distancesFitSixteenBits(const MapfGraph& graph) {
  if (graph.vertexCount() < 0xffff) return true;
  std::vector<int> depth(graph.vertexCount(), -1), queue;
  queue.reserve(graph.vertexCount());
  int eccentricity = 0;
  for (int root = 0; root < graph.vertexCount(); ++root) {
    if (depth[root] >= 0) continue;
    depth[root] = 0;
    queue.assign(1, root);
    for (std::size_t k = 0; k < queue.size(); ++k) {
      const int u = queue[k];
      eccentricity = std::max(eccentricity, depth[u]);
      for (const int w : graph.neighbours(u))
        if (depth[w] < 0) depth[w] = depth[u] + 1, queue.push_back(w);
    }
  }
  return 2 * eccentricity + 1 < 0xffff;
}

GoalDistanceTable::GoalDistanceTable(const MapfGraph& graph, std::span<const int> goals)
    : graph_(graph),
      vertices_(static_cast<std::size_t>(graph.vertexCount())),
      narrow_(distancesFitSixteenBits(graph)),
      row_of_agent_(goals.size()) {
  std::unordered_map<int, int> row_of_goal;
  for (std::size_t a = 0; a < goals.size(); ++a) {
    const auto [it, fresh] = row_of_goal.emplace(goals[a], static_cast<int>(row_of_goal.size()));
    row_of_agent_[a] = it->second;
    if (!fresh) continue;
    Frontier& f = frontiers_.emplace_back();
    f.ring.assign(16, 0);
    f.ring[0] = goals[a];
    f.size = 1;
    f.reached = 1;
  }
  const std::size_t n = frontiers_.size() * vertices_;
  if (narrow_)
    narrow_entries_.reset(zeroed<std::uint16_t>(n));
  else
    wide_entries_.reset(zeroed<std::uint32_t>(n));
  for (const auto& [goal, row] : row_of_goal) {
    const std::size_t i = static_cast<std::size_t>(row) * vertices_ + goal;
    if (narrow_)
      narrow_entries_[i] = 1;
    else
      wide_entries_[i] = 1;
  }
}

template <typename Entry>
std::uint32_t GoalDistanceTable::searchIn(Entry* entries, int row_index, int v) const {
  Frontier& f = frontiers_[row_index];
  Entry* row = entries + static_cast<std::size_t>(row_index) * vertices_;
  // Breadth first, one vertex's neighbours at a time, until v has its distance.
  while (f.size > 0 && row[v] == 0) {
    const int u = f.ring[f.head];
    f.head = (f.head + 1) & (f.ring.size() - 1);
    --f.size;
    const Entry next = static_cast<Entry>(row[u] + 1);
    for (const int w : graph_.neighbours(u)) {
      if (row[w] != 0) continue;
      row[w] = next;
      ++f.reached;
      if (f.size == f.ring.size()) {  // full: unroll into a ring twice the size
        std::vector<int> bigger(f.ring.size() * 2);
        for (std::size_t k = 0; k < f.size; ++k)
          bigger[k] = f.ring[(f.head + k) & (f.ring.size() - 1)];
        f.ring.swap(bigger);
        f.head = 0;
      }
      f.ring[(f.head + f.size) & (f.ring.size() - 1)] = w;
      ++f.size;
    }
  }
  return row[v] != 0 ? row[v] - 1u : kUnreachable;
}

std::uint32_t GoalDistanceTable::search(int agent, int v) const {
  const int row = row_of_agent_[agent];
  return narrow_ ? searchIn(narrow_entries_.get(), row, v) : searchIn(wide_entries_.get(), row, v);
}

std::size_t GoalDistanceTable::bytes() const {
  std::size_t frontier = 0;
  for (const Frontier& f : frontiers_) frontier += f.ring.capacity() * sizeof(int);
  return vertices_ * frontiers_.size() * (narrow_ ? 2 : 4) + frontier;
}

std::size_t GoalDistanceTable::bytesReached() const {
  std::size_t total = 0;
  for (const Frontier& f : frontiers_)
    total += f.reached * (narrow_ ? 2 : 4) + f.ring.capacity() * sizeof(int);
  return total;
}

std::string checkGoalsReachable(const GoalDistanceTable& distance, std::span<const int> starts,
                                const StopToken& deadline) {
  // Searches of different rows share nothing, so they run on all cores: each worker takes the
  // agents of every k-th row (agents sharing a goal share a row, so one worker owns each row).
  // The answer does not depend on the split: the lowest unreachable agent is named.
  const std::size_t n = starts.size();
  const std::size_t workers = std::clamp<std::size_t>(
      std::min<std::size_t>(std::thread::hardware_concurrency(), n / 64), 1, 8);
  std::vector<std::size_t> first_unreachable(workers, n);
  std::atomic<bool> out_of_time{false};
  const auto work = [&](std::size_t w) {
    for (std::size_t i = 0; i < n; ++i) {
      if (static_cast<std::size_t>(distance.rowOf(static_cast<int>(i))) % workers != w) continue;
      if (out_of_time.load(std::memory_order_relaxed) || deadline.expired()) {
        out_of_time = true;
        return;
      }
      if (distance(static_cast<int>(i), starts[i]) == GoalDistanceTable::kUnreachable) {
        first_unreachable[w] = i;
        return;
      }
    }
  };
  std::vector<std::thread> threads;
  for (std::size_t w = 1; w < workers; ++w) threads.emplace_back(work, w);
  work(0);
  for (auto& t : threads) t.join();
  const std::size_t lowest = *std::min_element(first_unreachable.begin(), first_unreachable.end());
  if (lowest < n) return "goal of agent " + std::to_string(lowest) + " is unreachable";
  if (out_of_time) return deadline.stopRequested() ? "stopped" : "time limit reached";
  return "";
}

}  // namespace cosim
