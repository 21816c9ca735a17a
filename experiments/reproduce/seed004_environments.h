#pragma once
// The three kinds of environment seed 004 planned its tests on (§6.2: "maze, open, puzzle 15")
// plus the bottleneck of §4.4, with robots placed at random on free cells as in the seed's
// software (distinct starts, distinct goals, §1.2). The seed publishes no maps; ours:
// - maze: its own generator (§4.1, planning/mapf/maze_generator.h), size as given;
// - open: an obstacle-free room of the same size;
// - bottleneck: two rooms joined by a single one-cell door in the middle of the dividing wall
//   ("WHCA* solves the bottleneck, but only for a small number of agents (2)", §4.4).
// The seed's "puzzle 15" is not explained in the text and is not reconstructed.
#include <cstdint>
#include <string>
#include <vector>

#include "planning/mapf/mapf_problem.h"

namespace cosim {

enum class Seed004Environment { kMaze, kOpen, kBottleneck };
const char* seed004EnvironmentName(Seed004Environment e);

// width x height map of that kind; the maze depends on seed.
OccupancyGrid seed004Map(Seed004Environment e, int width, int height, std::uint64_t seed);

// `robots` agents with random distinct starts and distinct goals on free cells (all in the one
// connected component, which every map here is). Throws InputError if there are too few cells.
MapfInstance randomlyPlacedRobots(const OccupancyGrid& grid, int robots, std::uint64_t seed,
                                  int connectivity = 4);

// The bottleneck with every robot forced through the door: random distinct starts left of the
// dividing wall (column width / 2), random distinct goals right of it. Throws InputError if a
// room has fewer free cells than robots.
MapfInstance robotsThroughTheDoor(const OccupancyGrid& grid, int robots, std::uint64_t seed,
                                  int connectivity = 4);

}  // namespace cosim
