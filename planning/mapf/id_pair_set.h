#pragma once
// A set of (from, to) pairs of 32-bit ids (the edges between LaCAM's configurations), so that an
// edge found again is recognised in constant time instead of by walking a node's successor list
// (a node near the goal can be expanded many thousand times in the anytime phase). Open
// addressing with linear probing, at most half full.
#include <cstdint>
#include <vector>

namespace cosim {

class IdPairSet {
 public:
  IdPairSet() : slots_(1024, kEmpty) {}

  // Adds the pair; false if it was there already.
  bool insert(std::uint32_t from, std::uint32_t to) {
    if (2 * (size_ + 1) > slots_.size()) grow();
    return place(slots_, (static_cast<std::uint64_t>(from) << 32) | to);
  }
  std::size_t bytes() const { return slots_.size() * sizeof(std::uint64_t); }

 private:
  static constexpr std::uint64_t kEmpty = ~std::uint64_t(0);  // (kNone, kNone): never an edge

  static std::size_t slotOf(std::uint64_t key, std::size_t mask) {
    key *= 0x9e3779b97f4a7c15ull;  // Fibonacci hashing (Knuth, TAOCP 3, §6.4)
    return static_cast<std::size_t>(key >> 32) & mask;
  }
  bool place(std::vector<std::uint64_t>& slots, std::uint64_t key) {
    const std::size_t mask = slots.size() - 1;
    for (std::size_t s = slotOf(key, mask);; s = (s + 1) & mask) {
      if (slots[s] == key) return false;
      if (slots[s] == kEmpty) {
        slots[s] = key;
        ++size_;
        return true;
      }
    }
  }
  void grow() {
    std::vector<std::uint64_t> bigger(slots_.size() * 2, kEmpty);
    size_ = 0;
    for (const std::uint64_t k : slots_)
      if (k != kEmpty) place(bigger, k);
    slots_.swap(bigger);
  }

  std::vector<std::uint64_t> slots_;
  std::size_t size_ = 0;
};

}  // namespace cosim
