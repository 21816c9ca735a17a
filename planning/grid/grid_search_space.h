#pragma once
// The graph that every grid search in this folder walks: the occupancy grid's own flat array,
// indexed by OccupancyGrid::index, and the allowed moves as index offsets. Building it is O(1),
// so a query costs only its search. Which moves are legal from a cell is decided with one bit
// mask per expansion: the free/blocked state of the cell's neighbours is read once (by raw index
// offsets away from the grid's border, bounds-checked on it), and each move needs a fixed subset
// of them free (its target, plus the side cells it sweeps past when corner cutting is off).
#include <cstdint>
#include <string>
#include <vector>

#include "planning/grid/grid_planner.h"
#include "planning/grid/grid_segment_checker.h"

namespace cosim {

// The connectivity in force on a grid of the given dimensionality: 0 means "all moves" (8 in 2D,
// 26 in 3D). Throws InputError (file, "parameter connectivity") when the value does not apply to
// the grid (4/8 are 2D values, 6/18/26 are 3D values).
GridMoves resolveGridMoves(const GridMoves& moves, bool three_d, const std::string& file = "");

// Exact-integer move costs for the searches whose costs are sums of moves (A*, Dijkstra,
// Bellman-Ford): 1, sqrt 2 and sqrt 3 in units of 2^-32 cells. Integer sums make equal f values
// compare equal (which the A* tie stack relies on) and make results independent of summation
// order; the rounding (< 2^-33 per move) cannot reorder distinct path lengths on any grid this
// program accepts, and reported lengths are recomputed in floating point from the cells.
using FixedCost = std::uint64_t;
constexpr double kFixedCostUnit = 4294967296.0;  // 2^32
constexpr FixedCost kFixedStraight = 4294967296ull;
constexpr FixedCost kFixedFaceDiagonal = 6074001000ull;  // round(sqrt(2) * 2^32)
constexpr FixedCost kFixedBodyDiagonal = 7439101574ull;  // round(sqrt(3) * 2^32)

class GridSearchSpace {
 public:
  struct Move {
    std::int64_t offset;  // index delta
    int dx, dy, dz;
    double cost;           // 1, sqrt 2 or sqrt 3
    FixedCost fixed_cost;  // the same in 2^-32 units
    std::uint32_t need;    // bits of neighbourMask() that must be set (free) for the move
    // Index deltas of the cells of the unit box the move spans, other than its origin: the
    // cells its segment touches (for the segment checks' shortcut).
    std::int64_t box[7];
    int box_cells;
  };

  // `moves` must already be resolved (resolveGridMoves). Keeps a reference to `grid` and to
  // `segments`, if given: then every move and line of sight is also checked against the
  // inflated obstacles (GridSegmentChecker), for grids judged at cell centres.
  GridSearchSpace(const OccupancyGrid& grid, const GridMoves& moves,
                  const GridSegmentChecker* segments = nullptr);

  const OccupancyGrid& grid() const { return *grid_; }
  std::size_t size() const { return grid_->cellCount(); }
  const std::vector<Move>& moves() const { return moves_; }

  std::uint32_t index(const Cell& c) const { return static_cast<std::uint32_t>(grid_->index(c)); }
  Cell cellOf(std::uint32_t i) const { return grid_->cellAt(i); }

  // Bit k set when the k-th neighbour that any move needs is free; c is the cell of index i.
  std::uint32_t neighbourMask(std::uint32_t i, const Cell& c) const {
    std::uint32_t mask = 0;
    const std::size_t n = probes_.size();
    if (c.x > 0 && c.y > 0 && c.x + 1 < nx_ && c.y + 1 < ny_ &&
        (nz_ == 1 || (c.z > 0 && c.z + 1 < nz_))) {
      const std::uint8_t* at = cells_ + i;
      for (std::size_t k = 0; k < n; ++k)
        mask |= static_cast<std::uint32_t>(at[probes_[k].offset] == 0) << k;
    } else {
      for (std::size_t k = 0; k < n; ++k) {
        const Probe& p = probes_[k];
        mask |= static_cast<std::uint32_t>(!grid_->blocked(c.x + p.dx, c.y + p.dy, c.z + p.dz))
                << k;
      }
    }
    return mask;
  }

  // Whether move m from cell u (cell c, neighbour mask `free`) may be made: the cells it needs
  // are free and, with segment checks, its segment clears the inflated obstacles.
  bool moveAllowed(std::uint32_t free, const Move& m, std::uint32_t u, const Cell& c) const {
    if ((free & m.need) != m.need) return false;
    if (segments_ == nullptr) return true;
    // Every cell of the move's box lies between u and its (free, so inside) target.
    const std::uint8_t* near = segments_->nearData() + u;
    bool far = near[0] == 0;
    for (int k = 0; far && k < m.box_cells; ++k) far = near[m.box[k]] == 0;
    return far || segments_->pointsClear(grid_->cellCenter(c),
                                         grid_->cellCenter({c.x + m.dx, c.y + m.dy, c.z + m.dz}));
  }

  // Supercover line of sight between two cells' centres (grid_line_of_sight.h), and with
  // segment checks clear of the inflated obstacles as well.
  bool lineOfSight(std::uint32_t a, std::uint32_t b) const;

 private:
  struct Probe {
    std::int64_t offset;
    int dx, dy, dz;
  };
  const OccupancyGrid* grid_;
  const GridSegmentChecker* segments_;
  const std::uint8_t* cells_;
  int nx_, ny_, nz_;
  std::vector<Probe> probes_;  // neighbours read by neighbourMask()
  std::vector<Move> moves_;
};

}  // namespace cosim
