#pragma once
// A radix heap (Ahuja, Mehlhorn, Orlin & Tarjan 1990) for the OPEN list of searches whose keys
// never fall below the last key taken out: A* with a consistent heuristic and Dijkstra, on the
// integer costs of grid_search_space.h. An entry with key k sits in bucket bit_length(k ^ last);
// taking the minimum redistributes one bucket into lower ones, so each entry moves at most 64
// times and most pushes and pops are a vector push_back/pop_back. Bucket 0 (keys equal to the
// last key) is served last-in first-out: among equal f, the deepest node goes first.
#include <cstdint>
#include <vector>

namespace cosim {

class GridRadixHeap {
 public:
  struct Entry {
    std::uint64_t f;
    std::uint32_t cell;
  };

  void clear() {
    for (auto& b : buckets_) b.clear();
    last_ = 0;
    size_ = 0;
  }
  bool empty() const { return size_ == 0; }

  // Requires e.f >= the key of the last entry popped (monotone use).
  void push(const Entry& e) {
    buckets_[bucketOf(e.f)].push_back(e);
    ++size_;
  }

  Entry pop() {
    if (buckets_[0].empty()) {
      int i = 1;
      while (buckets_[i].empty()) ++i;
      std::uint64_t least = buckets_[i].front().f;
      for (const Entry& e : buckets_[i]) least = e.f < least ? e.f : least;
      last_ = least;
      for (const Entry& e : buckets_[i]) buckets_[bucketOf(e.f)].push_back(e);
      buckets_[i].clear();
    }
    const Entry e = buckets_[0].back();
    buckets_[0].pop_back();
    --size_;
    return e;
  }

 private:
  int bucketOf(std::uint64_t key) const {
    return key == last_ ? 0 : 64 - __builtin_clzll(key ^ last_);
  }
  std::vector<Entry> buckets_[65];
  std::uint64_t last_ = 0;
  std::size_t size_ = 0;
};

}  // namespace cosim
