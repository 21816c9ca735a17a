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

// Obstacles a generated world may have: what a scenario may hold (the loader's limit, 10 000).
// Each generator estimates its count from its options and refuses more before generating any
// (a 10 km forest at density 0.5 would be 50 million trunks, over 10 GB).
constexpr double kMaxGeneratedObstacles = 10000;

// Throws InputError (place: "generator <name>") unless `expected` <= kMaxGeneratedObstacles.
void checkGeneratedObstacleCount(double expected, const std::string& generator);

// Throws InputError (place: "generator <name>") if the size is not positive on every axis or the
// density is outside [0, max_density].
void checkWorldGeneratorOptions(const WorldGeneratorOptions& o, double max_density,
                                const std::string& generator);

}  // namespace cosim
