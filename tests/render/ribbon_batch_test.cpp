// A team's lines as camera-facing ribbons: their triangles, their shadows on the floor, and the
// pixels they leave in a rendered team frame.
#include "render/ribbon_batch.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "render/run_renderer.h"
#include "render/vehicle_palette.h"
#include "render_test_scene.h"
#include "run/run_evaluation.h"
#include "sim/world_model.h"

using namespace cosim;

namespace {

struct Box {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e9), hi = Eigen::Vector3d::Constant(-1e9);
};

Box boundsOf(const std::vector<float>& xyz) {
  Box b;
  for (std::size_t i = 0; i + 2 < xyz.size(); i += 3)
    for (int k = 0; k < 3; ++k) {
      b.lo[k] = std::min<double>(b.lo[k], xyz[i + k]);
      b.hi[k] = std::max<double>(b.hi[k], xyz[i + k]);
    }
  return b;
}

}  // namespace

TEST(RibbonBatch, RibbonIsTwoRadiiWideAcrossTheSightLineAndLengthenedAtBothEnds) {
  RibbonBatch r;
  r.add({0, 0, 0}, {1, 0, 0}, {0.2f, 0.4f, 0.6f}, 0.1);
  std::vector<float> xyz, rgb;
  r.triangles({0.5, 0, 10}, xyz, rgb);  // looking down: the ribbon lies in the floor plane
  ASSERT_EQ(xyz.size(), 4u * 3u * 3u);  // two quads, four triangles
  const Box b = boundsOf(xyz);
  EXPECT_NEAR(b.lo.x(), -0.1, 1e-6);  // lengthened by the radius: no gap at joints
  EXPECT_NEAR(b.hi.x(), 1.1, 1e-6);
  EXPECT_NEAR(b.lo.y(), -0.1, 1e-6);
  EXPECT_NEAR(b.hi.y(), 0.1, 1e-6);
  EXPECT_NEAR(b.hi.z() - b.lo.z(), 0.0, 1e-6);
  // The middle shows the colour itself (the one the figures and viewer.html use), the edges are
  // darker, as a lit tube: blue 0.6 in the middle and 0.6 x 0.78 at the edges.
  float most = 0.0f, least = 1.0f;
  for (std::size_t i = 2; i < rgb.size(); i += 3) {
    most = std::max(most, rgb[i]);
    least = std::min(least, rgb[i]);
  }
  EXPECT_FLOAT_EQ(most, 0.6f);
  EXPECT_NEAR(least, 0.468f, 1e-6);
}

TEST(RibbonBatch, SeenEndOnTheRibbonStillCoversTheLineWidth) {
  RibbonBatch r;
  r.add({0, 0, 0}, {0, 0, 1}, {1, 1, 1}, 0.05);
  std::vector<float> xyz, rgb;
  r.triangles({0, 0, 5}, xyz, rgb);
  const Box b = boundsOf(xyz);
  const double across = std::max(b.hi.x() - b.lo.x(), b.hi.y() - b.lo.y());
  EXPECT_NEAR(across, 0.1, 1e-6);
}

TEST(RibbonBatch, ShadowFallsAlongTheLightOntoTheFloor) {
  RibbonBatch r;
  r.add({0, 0, 2}, {1, 0, 2}, {1, 0, 0}, 0.1);
  r.add({0, 0, -1}, {1, 0, -1}, {1, 0, 0}, 0.1);  // under the floor: no shadow
  std::vector<float> xyz;
  const Eigen::Vector3d light = Eigen::Vector3d(-0.3, -0.4, -1).normalized();
  r.shadowTriangles(light, 0.0, xyz);
  ASSERT_EQ(xyz.size(), 2u * 3u * 3u);  // one quad
  // 2 m up, the light moves 0.3 and 0.4 sideways per metre down: x - 0.6, y - 0.8.
  const Box b = boundsOf(xyz);
  EXPECT_NEAR(b.lo.x(), -0.6 - 0.1, 1e-6);
  EXPECT_NEAR(b.hi.x(), 1.0 - 0.6 + 0.1, 1e-6);
  EXPECT_NEAR(0.5 * (b.lo.y() + b.hi.y()), -0.8, 1e-6);
  EXPECT_NEAR(b.hi.y() - b.lo.y(), 0.2, 1e-6);
  EXPECT_NEAR(b.lo.z(), 0.01, 1e-6);  // a tenth of the radius above the floor
  EXPECT_NEAR(b.hi.z(), 0.01, 1e-6);
}

TEST(RibbonBatch, TeamTrailsAreDrawnInTheFrameWithTheirShadowsOnTheFloor) {
  // Two quadrotors flying the same straight line 4 m apart in y, seen from above.
  Scenario s = test::renderTestScenario(640, 360);
  s.vehicles.push_back(s.vehicles[0]);
  s.vehicles[1].name = "uav2";
  s.vehicles[1].start.y() += 4.0;
  s.vehicles[1].waypoints[0].y() += 4.0;
  const WorldModel world = WorldModel::build(s);
  RunLog log = test::straightFlightLog(4.0, 0.0);
  log.vehicles.push_back(log.vehicles[0]);
  log.vehicles[1].name = "uav2";
  log.vehicles[1].goal.y() += 4.0;
  for (LogSample& x : log.vehicles[1].samples) {
    x.pos.y() += 4.0;
    x.ref_pos.y() += 4.0;
  }
  const RunRecord renderer_record = recordOfLog(s, log, world);
  RunRenderer renderer(s, renderer_record, 640, 360);
  std::vector<std::uint8_t> rgb;
  renderer.render(4.0, "top", rgb, /*annotate=*/false);
  // Goals, starts, markers, arrows: two of each.
  EXPECT_EQ(renderer.lastFrameTimings().overlay_geoms, 8);
  EXPECT_GT(renderer.lastFrameTimings().ribbon_segments, 1);
  const auto pixel = [&](const Eigen::Vector3d& p) {
    Eigen::Vector2d px;
    EXPECT_TRUE(renderer.project(p, px));
    const std::size_t i = 3 * (static_cast<std::size_t>(px.y()) * 640 + px.x());
    return Eigen::Vector3i(rgb[i], rgb[i + 1], rgb[i + 2]);
  };
  // A team's trails are drawn in each member's own colour (render/vehicle_palette.h), unlit:
  // the pixel in a trail's middle is that colour.
  for (std::size_t v = 0; v < 2; ++v) {
    const Eigen::Vector3i c = pixel({10, 4.0 * static_cast<double>(v + 1), 2});
    const Eigen::Vector3f want = 255.0f * vehicleColour(v);
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(c[k], want[k], 30.0) << "trail of vehicle " << v << ", channel " << k;
  }
  // The sun's shadow of the trail 2 m up lands (0.6, 0.8) m off and darkens the floor there.
  const Eigen::Vector3i shade = pixel({10 - 0.6, 4 - 0.8, 0});
  const Eigen::Vector3i floor = pixel({10 - 0.6, 4 - 1.6, 0});
  EXPECT_LT(shade.sum() + 60, floor.sum());
}
