// The checkered floor keeps both shades in the views from above: neither square comes out
// white (the lighter ones used to be 255 in the overview and top views).
#include <gtest/gtest.h>

#include "render/run_renderer.h"
#include "render_test_scene.h"
#include "run/run_evaluation.h"
#include "sim/world_model.h"

using namespace cosim;
using namespace cosim::test;

namespace {

// The grey of the floor at world point p in the last frame.
int floorGrey(const RunRenderer& r, const std::vector<std::uint8_t>& rgb, Eigen::Vector3d p) {
  Eigen::Vector2d px;
  if (!r.project(p, px)) return -1;
  const int x = static_cast<int>(px.x()), y = static_cast<int>(px.y());
  if (x < 0 || y < 0 || x >= r.width() || y >= r.height()) return -1;
  const std::size_t i = (static_cast<std::size_t>(y) * r.width() + x) * 3;
  return (rgb[i] + rgb[i + 1] + rgb[i + 2]) / 3;
}

}  // namespace

TEST(FloorShading, NeitherCheckerSquareSaturatesFromAbove) {
  Scenario s = renderTestScenario(320, 180);
  s.world.obstacles.clear();
  s.vehicles[0].waypoints = {{4, 3, 2}};
  RunLog log = straightFlightLog(1.0, 0.0);
  for (LogSample& k : log.vehicles[0].samples) k.pos = k.ref_pos = {1, 1, 2};
  log.vehicles[0].planned_path = {{1, 1, 2}, {1.1, 1, 2}};
  log.vehicles[0].goal = {1.1, 1, 2};
  const WorldModel world = WorldModel::build(s);
  const RunRecord renderer_record = recordOfLog(s, log, world);
  RunRenderer renderer(s, renderer_record, 320, 180);
  std::vector<std::uint8_t> rgb;
  for (const char* camera : {"top", "overview"}) {
    renderer.render(0.5, camera, rgb, false);
    // Squares are 2 m (world_model.cpp): sample the centres of two neighbours mid-world.
    const int a = floorGrey(renderer, rgb, {11, 11, 0}), b = floorGrey(renderer, rgb, {13, 11, 0});
    ASSERT_GE(a, 0) << camera;
    ASSERT_GE(b, 0) << camera;
    EXPECT_LT(std::max(a, b), 245) << camera << ": a floor square is white";
    EXPECT_GE(std::abs(a - b), 6) << camera << ": the squares are not told apart";
  }
}
