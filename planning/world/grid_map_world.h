#pragma once
// A 2D grid map (a MovingAI .map, seed 004's warehouse and maze floors) as a world of boxes: the
// blocked cells, merged into as few axis-aligned boxes as a greedy sweep finds, standing on the
// floor. Cell (x, y) (x = column, y = row, as in MovingAI) covers [x, x+1) x [y, y+1) cells of
// `grid.cellSize()` metres from the grid's origin, so the world's coordinates and the map's cell
// indices agree: a robot in cell (x, y) stands at ((x + 0.5) c, (y + 0.5) c).
#include <cstddef>

#include "planning/grid/occupancy_grid.h"
#include "planning/world/world.h"

namespace cosim {

// Boxes a grid map may become, as many as a scenario's obstacles (sim/scenario_loader.cpp).
// MuJoCo's compiler and collision phase, the planners' worlds and the clearance metric all
// scale with the number of geoms: a 1000 x 1000 checkerboard's 500 000 boxes took MuJoCo over
// 160 s to load and gigabytes of memory; 20 000 boxes took 22 s. The maps in tests/data need at
// most 1 488 (Berlin_0_256), the warehouse 204.
constexpr std::size_t kMaxGridMapBoxes = 10000;

// `height`: the blocks' height (m); `ceiling`: the world's top (m, above the blocks: room for
// quadrotors overhead). The world's bounds are the map's footprint from z = 0 to `ceiling`.
// Throws InputError (no file, no place) once the boxes would exceed `max_boxes`, before making
// more.
World worldFromGridMap(const OccupancyGrid& grid, double height, double ceiling,
                       std::size_t max_boxes = kMaxGridMapBoxes);

}  // namespace cosim
