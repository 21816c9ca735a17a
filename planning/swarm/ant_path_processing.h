#pragma once
// The path post-processing the ant planners of seed 000 (MSAC, SACO, SACOdm; Pěňčík 2014) share,
// its §4.3.3: cycle removal and light smoothing, and the wider-range smoothing its author
// proposes, on paths of AntGridView cells.
#include <vector>

#include "planning/swarm/ant_grid_view.h"

namespace cosim {

// Seed 000 §4.3.3 path processing. `scratch` is a per-cell array that must hold -1 everywhere on
// entry; it is restored to -1 on exit (so a planner allocates it once per query).
class AntPathProcessing {
 public:
  explicit AntPathProcessing(const AntGridView& grid)
      : grid_(grid), position_(grid.cellCount(), -1) {}
  // Cuts every loop: when a cell recurs, everything between its two visits goes.
  void removeCycles(std::vector<int>& path);
  // Light smoothing: walking from the start, if a node has several later path nodes among its
  // legal neighbours, keep only the one with the highest index and drop the nodes in between.
  // Expects a loop-free path.
  void smoothLightly(std::vector<int>& path);
  // Wider-range smoothing, the extension the seed's author proposes (§6.1.4: [41]'s straight
  // path on scene 3 "would need smoothing over a wider range"): from each node, the farthest
  // node at most `range` path nodes ahead that a shortest obstacle-free 8-connected path reaches
  // (one of the two octile paths: diagonal run then straight run, or straight then diagonal)
  // replaces the nodes in between when it is shorter.
  void smoothWide(std::vector<int>& path, int range);

 private:
  // Appends to `out` the cells after a on an octile path to b (diagonal run first if
  // diagonal_first); false, leaving `out` as it was, if a cell or move is blocked.
  bool octilePath(int a, int b, bool diagonal_first, std::vector<int>& out) const;

  const AntGridView& grid_;
  std::vector<int> position_;  // index of a cell in the path being processed, or -1
};

}  // namespace cosim
