#pragma once
// How seed 002's grid agents (ants, GA's initial chromosomes, PSO's priority decoding) build a
// path: a walk from the start that at every cell picks one of the neighbourhood's moves. Seed 002
// forbids moves into "Black List" vertices; here the black list holds blocked cells, moves whose
// segment touches a blocked cell, and every cell this walk has already visited (so the candidates
// are the 3 of 4 or 7 of 8 neighbours the seed counts, minus obstacles). A walker with no
// candidate left steps back one cell (the dead end stays black-listed), so a walk never loops and
// ends either at the goal or, having visited every reachable cell, proves the goal unreachable.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "core/stop_token.h"
#include "planning/swarm/extended_neighbourhood.h"

namespace cosim {

enum class WalkOutcome { Reached, Unreachable, TimeUp };

class GridWalk {
 public:
  GridWalk(const OccupancyGrid& grid, const ExtendedNeighbourhood& moves)
      : grid_(grid),
        moves_(moves),
        visit_stamp_(grid.cellCount(), 0),
        legal_moves_(grid.cellCount(), 0),
        legal_known_(grid.cellCount(), 0) {}

  // choose(current cell, direction index of the move that reached it or -1, candidate direction
  // indices, count) returns the position in the candidate list of the move to make.
  // path receives start..goal; dirs the direction index of each move (dirs.size() + 1 ==
  // path.size()).
  template <class Choose>
  WalkOutcome walk(const Cell& start, const Cell& goal, Choose&& choose, const StopToken& deadline,
                   std::vector<Cell>& path, std::vector<int>& dirs) {
    if (++stamp_ == 0) {  // wrapped: clear the stamps once every 2^32 walks
      std::fill(visit_stamp_.begin(), visit_stamp_.end(), 0);
      stamp_ = 1;
    }
    path.assign(1, start);
    dirs.clear();
    visit_stamp_[grid_.index(start)] = stamp_;
    int candidates[32];
    while (!(path.back() == goal)) {
      if ((++steps_ & 1023) == 0 && deadline.expired()) return WalkOutcome::TimeUp;
      const Cell c = path.back();
      const std::uint32_t legal = legalMoves(c);
      int n = 0;
      for (int k = 0; k < moves_.directions(); ++k) {
        if (!(legal >> k & 1u)) continue;
        const NeighbourOffset& o = moves_.offset(k);
        if (visit_stamp_[grid_.index(c.x + o.dx, c.y + o.dy, c.z)] != stamp_) candidates[n++] = k;
      }
      if (n == 0) {  // dead end: back up, the dead cell stays black-listed
        path.pop_back();
        if (path.empty()) return WalkOutcome::Unreachable;
        dirs.pop_back();
        continue;
      }
      const int k = candidates[choose(c, dirs.empty() ? -1 : dirs.back(), candidates, n)];
      const Cell t{c.x + moves_.offset(k).dx, c.y + moves_.offset(k).dy, c.z};
      visit_stamp_[grid_.index(t)] = stamp_;
      path.push_back(t);
      dirs.push_back(k);
    }
    return WalkOutcome::Reached;
  }

  // Moves made (including steps back) over all walks: the "expansions" counter.
  std::uint64_t steps() const { return steps_; }

 private:
  // Bit k set: move k is legal from c. Computed on a cell's first visit (many ants pass there).
  std::uint32_t legalMoves(const Cell& c) {
    const std::size_t i = grid_.index(c);
    if (!legal_known_[i]) {
      std::uint32_t bits = 0;
      for (int k = 0; k < moves_.directions(); ++k)
        if (moves_.moveAllowed(grid_, c, k)) bits |= 1u << k;
      legal_moves_[i] = bits;
      legal_known_[i] = 1;
    }
    return legal_moves_[i];
  }

  const OccupancyGrid& grid_;
  const ExtendedNeighbourhood& moves_;
  std::vector<std::uint32_t> visit_stamp_;
  std::vector<std::uint32_t> legal_moves_;
  std::vector<std::uint8_t> legal_known_;
  std::uint32_t stamp_ = 0;
  std::uint64_t steps_ = 0;
};

// Roulette-wheel selection: index i with probability weights[i] / sum (uniform if all are 0).
inline int rouletteIndex(const double* weights, int n, std::mt19937_64& rng) {
  double total = 0.0;
  for (int i = 0; i < n; ++i) total += weights[i];
  if (!(total > 0.0)) return static_cast<int>(std::uniform_int_distribution<int>(0, n - 1)(rng));
  double r = std::uniform_real_distribution<double>(0.0, total)(rng);
  for (int i = 0; i < n; ++i) {
    r -= weights[i];
    if (r < 0.0) return i;
  }
  return n - 1;
}

// x^e with the exponents the seeds use computed without std::pow (it dominates the ants' time).
inline double powExponent(double x, double e) {
  if (e == 1.0) return x;
  if (e == 0.0) return 1.0;
  if (e == 2.0) return x * x;
  if (e == 0.5) return std::sqrt(x);
  return std::pow(x, e);
}

}  // namespace cosim
