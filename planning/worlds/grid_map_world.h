#pragma once
// A 2D grid map (a MovingAI .map, seed 004's warehouse and maze floors) as a world of boxes: the
// blocked cells, merged into as few axis-aligned boxes as a greedy sweep finds, standing on the
// floor. Cell (x, y) (x = column, y = row, as in MovingAI) covers [x, x+1) x [y, y+1) cells of
// `grid.cellSize()` metres from the grid's origin, so the world's coordinates and the map's cell
// indices agree: a robot in cell (x, y) stands at ((x + 0.5) c, (y + 0.5) c).
#include "planning/grid/occupancy_grid.h"
#include "planning/world/world.h"

namespace cosim {

// `height`: the blocks' height (m); `ceiling`: the world's top (m, above the blocks: room for
// quadrotors overhead). The world's bounds are the map's footprint from z = 0 to `ceiling`.
World worldFromGridMap(const OccupancyGrid& grid, double height, double ceiling);

}  // namespace cosim
