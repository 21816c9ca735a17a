#pragma once
// Seed 000's moving obstacles (Pěňčík 2014, §4.2.3): one cell in size, each moves in a straight
// line at a constant speed inside its bounding rectangle and turns to a random new direction when
// its next cell would be a static obstacle, the map's edge or outside the rectangle. Here that
// motion is drawn in advance from a seed (a route of straight runs between turns), so that every
// navigator meets the same traffic and a run is reproducible; the thesis's obstacles also turned
// away from the robot and from each other (lower ID first), which a fixed route cannot do.
#include <cstdint>

#include "planning/grid/occupancy_grid.h"
#include "planning/navigation/moving_obstacle.h"

namespace cosim {

struct TurningObstacleSpec {
  Cell start;              // a free cell inside the rectangle
  int direction = 0;       // initial direction, 0..7 counter-clockwise from +x
  double speed = 1.0;      // cells per time unit (the robot moves at 1)
  Cell box_min, box_max;   // the bounding rectangle, inclusive
  double travel = 4000.0;  // cells of route to draw (beyond it, the obstacle retraces it)
};

// The obstacle's route: the cells where it turns, from its start. Diagonal steps need both side
// cells free (no corner cutting). Throws InputError if the start is blocked or outside its
// rectangle, or if it is boxed in (no free neighbour).
MovingObstacle randomlyTurningObstacle(const OccupancyGrid& grid, const TurningObstacleSpec& spec,
                                       std::uint64_t seed);

}  // namespace cosim
