#include "planning/world/generators/generated_world.h"

#include <cmath>

#include "core/input_error.h"

namespace cosim {

void checkWorldGeneratorOptions(const WorldGeneratorOptions& o, double max_density,
                                const std::string& generator) {
  const std::string place = "generator " + generator;
  if (!o.size.allFinite() || (o.size.array() <= 0).any() || (o.size.array() > 10000).any())
    throw InputError("", place, "size must be positive and at most 10 km on every axis");
  if (!std::isfinite(o.density) || o.density < 0 || o.density > max_density)
    throw InputError("", place, "density must be in [0, " + std::to_string(max_density) + "]");
}

void checkGeneratedObstacleCount(double expected, const std::string& generator) {
  if (expected > kMaxGeneratedObstacles)
    throw InputError("", "generator " + generator,
                     "these options make about " +
                         std::to_string(static_cast<long long>(expected)) +
                         " obstacles, more than the " +
                         std::to_string(static_cast<long long>(kMaxGeneratedObstacles)) +
                         " a scenario may hold (a smaller size or density)");
}

}  // namespace cosim
