#pragma once
// Random forests: vertical cylinder trunks of random radius and height scattered uniformly over
// the ground. `density` is the fraction of the ground area covered by trunks (0.05 = a dense
// forest for a 0.45 m quadrotor). The start and the goal sit in opposite corners at 2 m, in
// clearings of `clearing` metres radius.
#include "planning/world/generators/generated_world.h"

namespace cosim {

struct ForestOptions {
  WorldGeneratorOptions world;
  double min_radius = 0.3, max_radius = 0.6;  // m
  double min_height_fraction = 0.5;           // of the world's height; trees reach up to it
  double clearing = 2.5;                      // m, free radius around start and goal
};

// Throws InputError for sizes or densities out of range (density in [0, 0.5]).
GeneratedWorld generateForest(const ForestOptions& options);

}  // namespace cosim
