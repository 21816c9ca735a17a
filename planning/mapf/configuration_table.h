#pragma once
// The configurations a LaCAM search has seen (LaCAM's EXPLORED: one vertex per agent), each with
// a dense id in order of insertion, found again by content: open addressing over a 64-bit hash,
// the stored hashes compared before the configurations themselves.
#include <cstdint>
#include <span>
#include <vector>

#include "planning/mapf/row_arena.h"

namespace cosim {

class ConfigurationTable {
 public:
  static constexpr std::uint32_t kAbsent = 0xffffffffu;

  explicit ConfigurationTable(std::size_t agents);

  static std::uint64_t hash(std::span<const int> configuration);
  // The id of an equal configuration, or kAbsent. `hash` is hash(configuration).
  std::uint32_t find(std::span<const int> configuration, std::uint64_t hash) const;
  // Adds a configuration known to be absent; returns its id (0, 1, 2, ...).
  std::uint32_t insert(std::span<const int> configuration, std::uint64_t hash);

  std::span<const int> operator[](std::uint32_t id) const { return {configs_.row(id), agents_}; }
  std::size_t size() const { return hashes_.size(); }
  std::size_t bytes() const;

 private:
  void grow();

  std::size_t agents_;
  RowArena<int> configs_;
  std::vector<std::uint64_t> hashes_;  // per id
  std::vector<std::uint32_t> slots_;   // id or kAbsent; size a power of two
};

}  // namespace cosim
