#pragma once
// The four test maps of seed 003 (Navratil 2019, chapter 4): one 2D map and three 3D maps, as
// worlds of axis-aligned boxes on a 1 m lattice. The thesis gives only the sizes, the number of
// obstacles, start and goal (its layouts exist only as figures), so the obstacle layouts here
// are reconstructions built to match the described situations; see each map's comment.
// Coordinates: the thesis's MATLAB cell index i (1-based) is the cell [i-1, i) m, so its start
// [3, 3] is the point (2.5, 2.5) m.
#include <string>
#include <vector>

#include "planning/grid/occupancy_grid.h"
#include "planning/world/world.h"

namespace cosim {

struct Seed003Map {
  std::string name;         // "2d", "3d-1", "3d-2", "3d-3"
  std::string description;  // the thesis's description, and what was reconstructed
  World world;
  Eigen::Vector3d start, goal;  // metres (cell centres)
  bool planar = false;          // the 2D map: plan on one layer
};

// In the thesis's order: 2D map ("space 1"), 3D maps 1-3 ("spaces 2-4").
std::vector<Seed003Map> seed003Maps();

// The map as the thesis's planners saw it: 1 m cells, a cell blocked exactly when its centre
// lies inside an obstacle (all box faces lie on whole metres, so the boxes are unions of cells),
// no inflation. One layer for the 2D map.
OccupancyGrid seed003Grid(const Seed003Map& map);

}  // namespace cosim
