#pragma once
// The OPEN list of the grid searches: a binary min-heap on f with lazy deletion (an improved
// cell is pushed again; the outdated entry is skipped when popped because its g no longer
// matches the node table). Ties on f go to the larger g, i.e. the deeper node, which expands
// fewer cells on grids with many equal-cost paths.
#include <cstdint>
#include <vector>

namespace cosim {

template <class Cost>
class GridOpenList {
 public:
  struct Entry {
    Cost f;
    Cost g;
    std::uint32_t cell;
  };

  void clear() { heap_.clear(); }
  bool empty() const { return heap_.empty(); }
  std::size_t size() const { return heap_.size(); }

  void push(const Entry& e) {
    std::size_t i = heap_.size();
    heap_.push_back(e);
    while (i > 0) {
      const std::size_t up = (i - 1) / 2;
      if (!before(e, heap_[up])) break;
      heap_[i] = heap_[up];
      i = up;
    }
    heap_[i] = e;
  }

  Entry pop() {
    const Entry top = heap_.front();
    const Entry last = heap_.back();
    heap_.pop_back();
    const std::size_t n = heap_.size();
    if (n > 0) {
      std::size_t i = 0;
      for (;;) {
        std::size_t child = 2 * i + 1;
        if (child >= n) break;
        if (child + 1 < n && before(heap_[child + 1], heap_[child])) ++child;
        if (!before(heap_[child], last)) break;
        heap_[i] = heap_[child];
        i = child;
      }
      heap_[i] = last;
    }
    return top;
  }

 private:
  static bool before(const Entry& a, const Entry& b) {
    return a.f < b.f || (a.f == b.f && a.g > b.g);
  }
  std::vector<Entry> heap_;
};

}  // namespace cosim
