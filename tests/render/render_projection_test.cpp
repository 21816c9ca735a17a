// Rendering a known scene off-screen: the planned path's pixels appear where the path projects.
#include <gtest/gtest.h>

#include "render/run_renderer.h"
#include "render_test_scene.h"
#include "run/run_evaluation.h"
#include "sim/world_model.h"

using namespace cosim;

namespace {

Scenario scene() {
  return test::renderTestScenario(640, 360);
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

  const RunRecord renderer_record = recordOfLog(s, log, world);

  RunRenderer renderer(s, renderer_record, 640, 360);
  std::vector<std::uint8_t> rgb;
  renderer.render(0.0, "overview", rgb, /*overlay_text=*/false);
  ASSERT_EQ(rgb.size(), 640u * 360u * 3u);

  // Points along both segments of the path must land on orange pixels (within 2 px).
  int hits = 0, tried = 0;
  for (int seg = 0; seg < 2; ++seg)
    for (double f : {0.3, 0.5, 0.7}) {
      const Eigen::Vector3d p =
          v.planned_path[seg] + f * (v.planned_path[seg + 1] - v.planned_path[seg]);
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

  // And a point of the floor well away from the path (and inside the frame) is not orange.
  Eigen::Vector2d away;
  ASSERT_TRUE(renderer.project({6, 16, 0}, away));
  ASSERT_TRUE(away.x() >= 0 && away.y() >= 0 && away.x() < 640 && away.y() < 360)
      << away.transpose();
  EXPECT_FALSE(isPlannedOrange(rgb, 640, static_cast<int>(away.x()), static_cast<int>(away.y())));
}

namespace {

// Pixels that differ between two frames (any channel by more than 24).
std::vector<bool> changedPixels(const std::vector<std::uint8_t>& a,
                                const std::vector<std::uint8_t>& b) {
  std::vector<bool> changed(a.size() / 3);
  for (std::size_t i = 0; i < changed.size(); ++i)
    for (int c = 0; c < 3; ++c)
      changed[i] = changed[i] || std::abs(int(a[3 * i + c]) - int(b[3 * i + c])) > 24;
  return changed;
}

}  // namespace

TEST(RenderProjection, VehiclePixelsAreWhereTheVehicleProjects) {
  const Scenario s = scene();
  const WorldModel world = WorldModel::build(s);
  // The same frame twice, with the vehicle at A and then far outside the view: the pixels that
  // change around A's projection are the vehicle (and its marker), centred on the projection.
  const Eigen::Vector3d A(12, 7, 4.5);
  std::vector<std::uint8_t> with, without;
  Eigen::Vector2d px;
  for (int pass = 0; pass < 2; ++pass) {
    RunLog log;
    VehicleLog& v = log.vehicles.emplace_back();
    v.name = "uav1";
    v.radius = 0.35;
    v.goal = s.vehicles[0].goal();
    v.planned_path = {{3, 3, 2}, {17, 5, 2}};  // start and goal markers away from A
    LogSample sample;
    sample.pos = pass == 0 ? A : Eigen::Vector3d(300, 300, -100);
    v.samples.push_back(sample);
    const RunRecord renderer_record = recordOfLog(s, log, world);
    RunRenderer renderer(s, renderer_record, 640, 360);
    renderer.render(0.0, "overview", pass == 0 ? with : without, /*annotate=*/false);
    if (pass == 0) {
      ASSERT_TRUE(renderer.project(A, px));
    }
  }
  const std::vector<bool> changed = changedPixels(with, without);

  // The changed pixels within 20 px of the projection (the vehicle and its marker are ~16 px
  // across here; its shadow on the floor falls ~35 px below).
  double sx = 0, sy = 0;
  int n = 0;
  for (int y = 0; y < 360; ++y)
    for (int x = 0; x < 640; ++x)
      if (changed[static_cast<std::size_t>(y) * 640 + x] &&
          std::hypot(x + 0.5 - px.x(), y + 0.5 - px.y()) < 20) {
        sx += x + 0.5;
        sy += y + 0.5;
        ++n;
      }
  ASSERT_GT(n, 20) << "no vehicle near its projection at " << px.transpose();
  EXPECT_NEAR(sx / n, px.x(), 3.0);
  EXPECT_NEAR(sy / n, px.y(), 3.0);
  // And the pixel at the projection itself changed.
  EXPECT_TRUE(changed[static_cast<std::size_t>(std::lround(px.y())) * 640 +
                      static_cast<std::size_t>(std::lround(px.x()))]);
}

TEST(RenderProjection, ChaseCameraKeepsTheVehicleAndThePathAheadInView) {
  const Scenario s = scene();
  const WorldModel world = WorldModel::build(s);
  RunLog log;
  VehicleLog& v = log.vehicles.emplace_back();
  v.name = "uav1";
  v.radius = 0.35;
  v.goal = s.vehicles[0].goal();
  for (int k = 0; k <= 500; ++k) {
    LogSample sample;
    sample.t = k / 100.0;
    sample.pos = Eigen::Vector3d(3, 3, 2) + sample.t * Eigen::Vector3d(3, 1, 0.2);
    v.samples.push_back(sample);
  }
  const RunRecord renderer_record = recordOfLog(s, log, world);
  RunRenderer renderer(s, renderer_record, 320, 180);
  std::vector<std::uint8_t> rgb;
  for (double t : {0.5, 2.0, 3.0}) {
    renderer.render(t, "chase", rgb, false);
    const Eigen::Vector3d here = v.samples[static_cast<std::size_t>(t * 100)].pos;
    const Eigen::Vector3d ahead = v.samples[static_cast<std::size_t>((t + 1.5) * 100)].pos;
    Eigen::Vector2d px, ahead_px;
    ASSERT_TRUE(renderer.project(here, px));
    ASSERT_TRUE(renderer.project(ahead, ahead_px));
    // The camera aims ahead of the vehicle: the vehicle sits in the middle third across, below
    // the middle but well inside the frame, and where it will be in 1.5 s is in the frame above
    // it. Near this small world's edge the camera tilts down (which shortens the view ahead) and
    // turns toward the world's centre rather than show the sky past the edge (which moves the
    // vehicle off the centre line and the path ahead toward the frame's side, still inside it).
    EXPECT_NEAR(px.x(), 160.0, 53.0) << "t = " << t;
    EXPECT_GT(px.y(), 90.0) << "t = " << t;
    EXPECT_LT(px.y(), 150.0) << "t = " << t;
    EXPECT_LT(ahead_px.y(), px.y() - 10.0) << "t = " << t;
    EXPECT_GT(ahead_px.y(), 0.0) << "t = " << t;
    EXPECT_GT(ahead_px.x(), 0.0) << "t = " << t;
    EXPECT_LT(ahead_px.x(), 320.0) << "t = " << t;
  }
}

namespace {
// Pixels clearly of the heading arrow's magenta.
bool isHeadingMagenta(const std::uint8_t* p) {
  return p[0] > 150 && p[2] > 130 && p[1] < 90;
}
}  // namespace

TEST(RenderProjection, HeadingArrowPointsWhereTheVehicleGoes) {
  const Scenario s = scene();
  const WorldModel world = WorldModel::build(s);
  const Eigen::Vector3d A(12, 7, 4.5);
  // Facing +x both times (yaw 0): the arrow follows the velocity, not the nose.
  for (double vx : {1.5, -1.5}) {
    RunLog log;
    VehicleLog& v = log.vehicles.emplace_back();
    v.name = "uav1";
    v.radius = 0.35;
    v.goal = s.vehicles[0].goal();
    v.planned_path = {{3, 3, 2}, {17, 5, 2}};
    LogSample sample;
    sample.pos = A;
    sample.vel = {vx, 0.0, 0.0};
    v.samples.push_back(sample);
    const RunRecord renderer_record = recordOfLog(s, log, world);
    RunRenderer renderer(s, renderer_record, 640, 360);
    std::vector<std::uint8_t> rgb;
    renderer.render(0.0, "top", rgb, false);
    Eigen::Vector2d centre, east;
    ASSERT_TRUE(renderer.project(A, centre));
    ASSERT_TRUE(renderer.project(A + Eigen::Vector3d(1, 0, 0), east));
    // The magenta pixels' mean lies on the side the vehicle faces (+x is screen right here).
    double sx = 0.0;
    int n = 0;
    for (int y = 0; y < 360; ++y)
      for (int x = 0; x < 640; ++x)
        if (isHeadingMagenta(rgb.data() + 3 * (static_cast<std::size_t>(y) * 640 + x))) {
          sx += x + 0.5;
          ++n;
        }
    ASSERT_GT(n, 10) << "no heading arrow at velocity " << vx;
    const double side = (sx / n - centre.x()) / (east.x() - centre.x());
    if (vx > 0.0)
      EXPECT_GT(side, 0.5);
    else
      EXPECT_LT(side, -0.5);
  }
}
