#include "planning/world/generators/city_generator.h"

#include <cmath>

#include "core/input_error.h"

namespace cosim {

GeneratedWorld generateCity(const CityOptions& o) {
  checkWorldGeneratorOptions(o.world, 1.0, "city");
  const Eigen::Vector3d size = o.world.size;
  if (!(o.street > 0 && o.pitch > o.street && o.min_height_fraction > 0 &&
        o.min_height_fraction <= 1 && o.min_footprint_fraction > 0 &&
        o.min_footprint_fraction <= 1))
    throw InputError("", "generator city", "pitch, street or fractions out of range");
  // Lots per axis, and the offset that centres the street grid in the world.
  const int nx = static_cast<int>(std::floor((size.x() - o.street) / o.pitch));
  const int ny = static_cast<int>(std::floor((size.y() - o.street) / o.pitch));
  if (nx < 1 || ny < 1 || size.z() < 3)
    throw InputError("", "generator city",
                     "world too small for one lot between streets (and 3 m of height)");
  checkGeneratedObstacleCount(static_cast<double>(nx) * ny, "city");  // one block per lot at most
  const double ox = (size.x() - (nx * o.pitch + o.street)) / 2;
  const double oy = (size.y() - (ny * o.pitch + o.street)) / 2;

  GeneratedWorld g;
  g.world.bounds_min = Eigen::Vector3d::Zero();
  g.world.bounds_max = size;
  const double flight_z = std::min(2.0, size.z() / 2);
  g.start = {ox + o.street / 2, oy + o.street / 2, flight_z};
  g.goal = {ox + nx * o.pitch + o.street / 2, oy + ny * o.pitch + o.street / 2, flight_z};

  std::mt19937_64 rng(o.world.seed);
  const double lot = o.pitch - o.street;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      // Every lot draws the same number of values, built or not, so one lot's outcome does not
      // shift the others'.
      const bool built = unitDraw(rng) < o.world.density;
      const double ex = uniformDraw(rng, o.min_footprint_fraction, 1.0) * lot;
      const double ey = uniformDraw(rng, o.min_footprint_fraction, 1.0) * lot;
      const double dx = uniformDraw(rng, -0.5, 0.5) * (lot - ex);
      const double dy = uniformDraw(rng, -0.5, 0.5) * (lot - ey);
      const double h = uniformDraw(rng, o.min_height_fraction, 1.0) * size.z();
      if (!built) continue;
      Obstacle b;
      b.type = ObstacleType::Box;
      b.pos = {ox + i * o.pitch + o.street + lot / 2 + dx,
               oy + j * o.pitch + o.street + lot / 2 + dy, h / 2};
      b.size = {ex, ey, h};
      g.world.obstacles.push_back(b);
    }
  return g;
}

}  // namespace cosim
