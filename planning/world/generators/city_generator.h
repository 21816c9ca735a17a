#pragma once
// City blocks: a street grid whose lots each hold, with probability `density`, one box building of
// random footprint and height. Streets are never built on, so start (one corner crossing) and goal
// (the opposite one) are always connected at street level, whatever the seed.
#include "planning/world/generators/generated_world.h"

namespace cosim {

struct CityOptions {
  WorldGeneratorOptions world;
  double pitch = 10.0;                  // m, lot spacing (street centre to street centre)
  double street = 4.0;                  // m, street width
  double min_height_fraction = 0.2;     // building heights in [min, 1] x world height
  double min_footprint_fraction = 0.6;  // building edge in [min, 1] x (pitch - street)
};

// Throws InputError if the world cannot hold one lot or density is outside [0, 1].
GeneratedWorld generateCity(const CityOptions& options);

}  // namespace cosim
