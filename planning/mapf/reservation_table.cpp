#include "planning/mapf/reservation_table.h"

#include <algorithm>

namespace cosim {

ReservationTable::ReservationTable(const MapfGrid& grid)
    : grid_(&grid),
      parked_from_(grid.cellCount(), kForever),
      last_reserved_(grid.cellCount(), -1) {}

void ReservationTable::reservePath(const std::vector<int>& cells, int start_time, bool park) {
  for (std::size_t i = 0; i < cells.size(); ++i) {
    const int t = start_time + static_cast<int>(i);
    const int c = cells[i];
    cells_.insert(key(static_cast<std::uint32_t>(c), t));
    if (last_reserved_[c] < 0 && parked_from_[c] == kForever) touched_.push_back(c);
    last_reserved_[c] = std::max(last_reserved_[c], t);
    if (i + 1 < cells.size() && cells[i + 1] != c)
      moves_.insert(key(grid_->moveKey(c, cells[i + 1]), t));
    static_from_ = std::max(static_from_, t + 1);
  }
  if (park && !cells.empty()) {
    const int last_t = start_time + static_cast<int>(cells.size()) - 1;
    parked_from_[cells.back()] = std::min(parked_from_[cells.back()], last_t);
  }
}

void ReservationTable::clear() {
  cells_.clear();
  moves_.clear();
  for (const int c : touched_) {
    parked_from_[c] = kForever;
    last_reserved_[c] = -1;
  }
  touched_.clear();
  static_from_ = 0;
}

bool ReservationTable::cellBlocked(int cell, int t) const {
  return t >= parked_from_[cell] || cells_.count(key(static_cast<std::uint32_t>(cell), t)) != 0;
}

bool ReservationTable::moveBlocked(int from, int to, int t) const {
  return moves_.count(key(grid_->moveKey(from, to), t)) != 0;
}

int ReservationTable::lastBlockedTime(int cell) const {
  return parked_from_[cell] != kForever ? kForever : last_reserved_[cell];
}

}  // namespace cosim
