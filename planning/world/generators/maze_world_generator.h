#pragma once
// Indoor mazes: seed 004's maze (planning/mapf/maze_generator.h, always connected) extruded into
// full-height walls of `cell` metres per grid cell. `density` is the fraction of the maze's inner
// walls kept: 1 = the perfect maze (one way between any two points), lower values knock out
// random wall cells between corridors and open loops (removing walls never disconnects it).
// Runs of wall cells along x become one box, which keeps the MuJoCo model small.
#include "planning/world/generators/generated_world.h"

namespace cosim {

struct MazeWorldOptions {
  WorldGeneratorOptions world;
  double cell = 3.0;  // m, corridor and wall width
};

// Start: the centre of cell (0, 0); goal: the farthest-indexed corridor cell; both at mid height.
// Throws InputError if fewer than 3 x 3 cells fit or density is outside [0, 1].
GeneratedWorld generateMazeWorld(const MazeWorldOptions& options);

}  // namespace cosim
