#pragma once
// A synthetic world for experiment sweeps: obstacles plus a start and a goal that are known to be
// clear of them. Generators are deterministic in their seed (std::mt19937_64, no distribution
// classes, whose output differs between standard libraries).
#include <cstdint>
#include <random>
#include <string>

#include "planning/world/world.h"

namespace cosim {

struct WorldGeneratorOptions {
  Eigen::Vector3d size{50, 50, 10};  // m; the world spans [0, size]
  double density = 0.05;             // meaning depends on the generator (see each header)
  std::uint64_t seed = 1;
};

struct GeneratedWorld {
  World world;
  Eigen::Vector3d start = Eigen::Vector3d::Zero();
  Eigen::Vector3d goal = Eigen::Vector3d::Zero();
};

// A uniform draw in [0, 1) from the top 53 bits (portable across standard libraries).
inline double unitDraw(std::mt19937_64& rng) {
  return static_cast<double>(rng() >> 11) * 0x1.0p-53;
}
inline double uniformDraw(std::mt19937_64& rng, double lo, double hi) {
  return lo + (hi - lo) * unitDraw(rng);
}

// Throws InputError (place: "generator <name>") if the size is not positive on every axis or the
// density is outside [0, max_density].
void checkWorldGeneratorOptions(const WorldGeneratorOptions& o, double max_density,
                                const std::string& generator);

}  // namespace cosim
