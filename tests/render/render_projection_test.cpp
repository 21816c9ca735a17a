// Rendering a known scene off-screen: the planned path's pixels appear where the path projects.
#include <gtest/gtest.h>

#include "render/run_renderer.h"
#include "sim/world_model.h"

using namespace cosim;

namespace {

Scenario scene() {
  Scenario s;
  s.file = "test";
  s.world.bounds_min = {0, 0, 0};
  s.world.bounds_max = {20, 20, 6};
  Obstacle box;
  box.type = ObstacleType::Box;
  box.pos = {10, 14, 2};
  box.size = {2, 2, 4};
  s.world.obstacles.push_back(box);
  VehicleSpec v;
  v.name = "uav1";
  v.model = "quad_1500g";
  v.model_file = modelsDirectory() / "quad_1500g.xml";
  v.start = {3, 3, 2};
  v.waypoints = {{17, 5, 2}};
  s.vehicles.push_back(v);
  s.render.width = 640;
  s.render.height = 360;
  return s;
}

// True if the pixel is clearly the planned path's orange (red high, blue low).
bool isPlannedOrange(const std::vector<std::uint8_t>& rgb, int w, int x, int y) {
  const std::uint8_t* p = rgb.data() + 3 * (static_cast<std::size_t>(y) * w + x);
  return p[0] > 180 && p[2] < 90 && p[0] > p[1] + 60;
}

}  // namespace

TEST(RenderProjection, PlannedPathPixelsAreWhereThePathProjects) {
  const Scenario s = scene();
  const WorldModel world = WorldModel::build(s);
  RunLog log;
  VehicleLog& v = log.vehicles.emplace_back();
  v.name = "uav1";
  v.radius = 0.35;
  v.goal = s.vehicles[0].goal();
  v.planned_path = {{3, 3, 2}, {10, 6, 3}, {17, 5, 2}};
  LogSample sample;
  sample.pos = {3, 3, 2};
  v.samples.push_back(sample);

  RunRenderer renderer(world, s, log, 640, 360);
  std::vector<std::uint8_t> rgb;
  renderer.render(0.0, "overview", rgb, /*overlay_text=*/false);
  ASSERT_EQ(rgb.size(), 640u * 360u * 3u);

  // Points along both segments of the path must land on orange pixels (within 2 px).
  int hits = 0, tried = 0;
  for (int seg = 0; seg < 2; ++seg)
    for (double f : {0.3, 0.5, 0.7}) {
      const Eigen::Vector3d p = v.planned_path[seg] + f * (v.planned_path[seg + 1] - v.planned_path[seg]);
      Eigen::Vector2d px;
      ASSERT_TRUE(renderer.project(p, px));
      ++tried;
      bool found = false;
      for (int dy = -2; dy <= 2 && !found; ++dy)
        for (int dx = -2; dx <= 2 && !found; ++dx) {
          const int x = static_cast<int>(px.x()) + dx, y = static_cast<int>(px.y()) + dy;
          if (x >= 0 && y >= 0 && x < 640 && y < 360) found = isPlannedOrange(rgb, 640, x, y);
        }
      hits += found ? 1 : 0;
    }
  EXPECT_EQ(hits, tried);

  // And a point well away from the path (the far corner of the floor) is not orange.
  Eigen::Vector2d corner;
  ASSERT_TRUE(renderer.project({19, 19, 0}, corner));
  EXPECT_FALSE(isPlannedOrange(rgb, 640, static_cast<int>(corner.x()), static_cast<int>(corner.y())));
}
