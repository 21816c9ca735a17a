#pragma once
// The reservation table of Cooperative A* (Silver 2005; seed 004 §3.3.2): which cells and moves
// the agents planned so far occupy at which times. Sparse, as the seed recommends: hash sets of
// reserved (cell, t) and (move, t) entries. A moving agent also reserves the space its move
// sweeps (MapfGrid::moveKey), which removes swap and crossing-diagonal conflicts (the seed's fix:
// reserve origin and destination at once). An agent parked at its goal reserves that cell from
// its arrival on, for ever.
#include <cstdint>
#include <unordered_set>
#include <vector>

#include "planning/mapf/mapf_grid.h"
#include "planning/mapf/space_time_constraints.h"

namespace cosim {

class ReservationTable final : public SpaceTimeConstraints {
 public:
  explicit ReservationTable(const MapfGrid& grid);

  // Reserves cells[i] at start_time + i and the moves between; park: the last cell stays
  // reserved for ever afterwards.
  void reservePath(const std::vector<int>& cells, int start_time, bool park);
  void clear();

  bool cellBlocked(int cell, int t) const override;
  bool moveBlocked(int from, int to, int t) const override;
  int lastBlockedTime(int cell) const override;
  int staticFrom() const override { return static_from_; }

 private:
  static std::uint64_t key(std::uint32_t what, int t) {
    return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(t)) << 32) | what;
  }
  const MapfGrid* grid_;
  std::unordered_set<std::uint64_t> cells_, moves_;
  std::vector<int> parked_from_;  // kForever: not parked
  std::vector<int> last_reserved_;
  std::vector<int> touched_;  // cells with a parked_from_/last_reserved_ entry, for clear()
  int static_from_ = 0;
};

}  // namespace cosim
