#include "planning/mapf/configuration_table.h"

#include <algorithm>

namespace cosim {

ConfigurationTable::ConfigurationTable(std::size_t agents)
    : agents_(agents), configs_(agents), slots_(1024, kAbsent) {}

std::uint64_t ConfigurationTable::hash(std::span<const int> configuration) {
  // Multiply-xorshift per vertex, then SplitMix64's finaliser (Steele et al. 2014) to spread
  // the bits over the table index.
  std::uint64_t h = 0x243f6a8885a308d3ull;
  for (const int v : configuration) {
    h = (h ^ static_cast<std::uint32_t>(v)) * 0x9e3779b97f4a7c15ull;
    h ^= h >> 32;
  }
  h = (h ^ (h >> 30)) * 0xbf58476d1ce4e5b9ull;
  h = (h ^ (h >> 27)) * 0x94d049bb133111ebull;
  return h ^ (h >> 31);
}

std::uint32_t ConfigurationTable::find(std::span<const int> configuration,
                                       std::uint64_t hash) const {
  const std::size_t mask = slots_.size() - 1;
  for (std::size_t s = hash & mask;; s = (s + 1) & mask) {
    const std::uint32_t id = slots_[s];
    if (id == kAbsent) return kAbsent;
    if (hashes_[id] == hash &&
        std::equal(configuration.begin(), configuration.end(), configs_.row(id)))
      return id;
  }
}

std::uint32_t ConfigurationTable::insert(std::span<const int> configuration, std::uint64_t hash) {
  if (2 * (hashes_.size() + 1) > slots_.size()) grow();
  const auto id = static_cast<std::uint32_t>(configs_.append());
  std::copy(configuration.begin(), configuration.end(), configs_.row(id));
  hashes_.push_back(hash);
  const std::size_t mask = slots_.size() - 1;
  std::size_t s = hash & mask;
  while (slots_[s] != kAbsent) s = (s + 1) & mask;
  slots_[s] = id;
  return id;
}

void ConfigurationTable::grow() {
  std::vector<std::uint32_t> bigger(slots_.size() * 2, kAbsent);
  const std::size_t mask = bigger.size() - 1;
  for (std::uint32_t id = 0; id < hashes_.size(); ++id) {
    std::size_t s = hashes_[id] & mask;
    while (bigger[s] != kAbsent) s = (s + 1) & mask;
    bigger[s] = id;
  }
  slots_.swap(bigger);
}

std::size_t ConfigurationTable::bytes() const {
  return configs_.bytes() + hashes_.capacity() * sizeof(std::uint64_t) +
         slots_.size() * sizeof(std::uint32_t);
}

}  // namespace cosim
