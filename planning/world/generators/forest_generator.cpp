#include "planning/world/generators/forest_generator.h"

#include <cmath>

#include "core/input_error.h"

namespace cosim {

GeneratedWorld generateForest(const ForestOptions& o) {
  checkWorldGeneratorOptions(o.world, 0.5, "forest");
  const Eigen::Vector3d size = o.world.size;
  if (!(o.min_radius > 0 && o.max_radius >= o.min_radius && o.min_height_fraction > 0 &&
        o.min_height_fraction <= 1 && o.clearing >= 0))
    throw InputError("", "generator forest", "radii, height fraction or clearing out of range");
  if (size.x() < 2 * o.clearing + 1 || size.y() < 2 * o.clearing + 1 || size.z() < 3)
    throw InputError("", "generator forest",
                     "world too small for the start and goal clearings (and 3 m of height)");

  GeneratedWorld g;
  g.world.bounds_min = Eigen::Vector3d::Zero();
  g.world.bounds_max = size;
  const double flight_z = std::min(2.0, size.z() / 2);
  g.start = {o.clearing, o.clearing, flight_z};
  g.goal = {size.x() - o.clearing, size.y() - o.clearing, flight_z};

  // Trunk count from the covered area: E[pi r^2] for r uniform in [a, b] is pi (a^2 + ab + b^2)/3.
  const double a = o.min_radius, b = o.max_radius;
  const double mean_disc = M_PI * (a * a + a * b + b * b) / 3.0;
  const double expected = o.world.density * size.x() * size.y() / mean_disc;
  checkGeneratedObstacleCount(expected, "forest");
  const auto wanted = static_cast<std::size_t>(std::llround(expected));
  std::mt19937_64 rng(o.world.seed);
  // Trunks that would stand in a clearing are redrawn; the attempt cap bounds the work when the
  // clearings take much of a small world.
  for (std::size_t attempts = 0; g.world.obstacles.size() < wanted && attempts < 20 * wanted + 100;
       ++attempts) {
    const double r = uniformDraw(rng, a, b);
    const double x = uniformDraw(rng, r, size.x() - r);
    const double y = uniformDraw(rng, r, size.y() - r);
    const double h = uniformDraw(rng, o.min_height_fraction, 1.0) * size.z();
    const Eigen::Vector2d c(x, y);
    if ((c - g.start.head<2>()).norm() < o.clearing + r ||
        (c - g.goal.head<2>()).norm() < o.clearing + r)
      continue;
    Obstacle t;
    t.type = ObstacleType::Cylinder;
    t.pos = {x, y, h / 2};
    t.radius = r;
    t.height = h;
    g.world.obstacles.push_back(t);
  }
  return g;
}

}  // namespace cosim
