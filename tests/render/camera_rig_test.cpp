// Camera poses of the named views, from the log alone.
#include "render/camera_rig.h"

#include <gtest/gtest.h>

#include "render/run_renderer.h"
#include "render_test_scene.h"
#include "run/run_evaluation.h"
#include "sim/world_model.h"

using namespace cosim;
using namespace cosim::test;

TEST(CameraRig, FixedCameraSitsAtItsPositionLookingAtItsTarget) {
  Scenario s = renderTestScenario();
  s.render.has_fixed_camera = true;
  s.render.fixed_pos = {-5, 10, 8};
  s.render.fixed_lookat = {10, 10, 1};
  const RunLog log = straightFlightLog(2.0);
  const CameraRig rig(s, log, 16.0 / 9.0);
  const CameraPose p = rig.pose(CameraKind::Fixed, 1.0);
  EXPECT_LT((p.eye() - s.render.fixed_pos).norm(), 1e-9);
  EXPECT_LT((p.lookat - s.render.fixed_lookat).norm(), 1e-9);
  EXPECT_NEAR(p.azimuth, 0.0, 1e-9);  // looking along +x
  EXPECT_LT(p.elevation, 0.0);        // and down
}

TEST(CameraRig, OrbitKeepsItsDistanceAndTurnsWithTime) {
  const Scenario s = renderTestScenario();
  const RunLog log = straightFlightLog(2.0);
  const CameraRig rig(s, log, 16.0 / 9.0);
  const CameraPose a = rig.pose(CameraKind::Orbit, 0.0), b = rig.pose(CameraKind::Orbit, 5.0);
  EXPECT_NEAR(a.distance, b.distance, 1e-12);
  // One turn per max(20 s, flight): 5 s of a 20 s period is a quarter turn.
  EXPECT_NEAR(b.azimuth - a.azimuth, 90.0, 1e-9);
}

TEST(CameraRig, TopViewIsNearlyOrthographicAndFitsTheWorld) {
  const Scenario s = renderTestScenario(320, 180);
  const WorldModel world = WorldModel::build(s);
  const RunLog log = straightFlightLog(2.0);
  const RunRecord renderer_record = recordOfLog(s, log, world);
  RunRenderer renderer(s, renderer_record, 320, 180);
  std::vector<std::uint8_t> rgb;
  renderer.render(1.0, "top", rgb, false);
  Eigen::Vector2d lo, hi, high_point, low_point;
  ASSERT_TRUE(renderer.project({0, 0, 0}, lo));
  ASSERT_TRUE(renderer.project({20, 20, 0}, hi));
  // +x right, +y up on screen, the 20 m height of the world filling ~94 % of the 180 rows.
  EXPECT_GT(hi.x(), lo.x());
  EXPECT_LT(hi.y(), lo.y());
  EXPECT_NEAR(lo.y() - hi.y(), 180.0 / 1.06, 3.0);
  EXPECT_NEAR(0.5 * (lo.x() + hi.x()), 160.0, 1.0);
  // Nearly orthographic: a point 6 m up projects within 6 px of the floor point below it,
  // even at the world's corner (through the model's 45-degree lens it would move ~36 px).
  ASSERT_TRUE(renderer.project({20, 20, 6}, high_point));
  ASSERT_TRUE(renderer.project({20, 20, 0}, low_point));
  EXPECT_LT((high_point - low_point).norm(), 6.0);
}

TEST(CameraRig, ChaseCameraMovesInRatherThanStandInsideAnObstacle) {
  Scenario s = renderTestScenario();
  // A block hanging over the straight flight (4 to 10 m up; the vehicle passes under it at
  // 2 m), where the camera behind and above the vehicle wants to be.
  Obstacle block;
  block.type = ObstacleType::Box;
  block.pos = {7.5, 4, 7};
  block.size = {3, 6, 6};
  s.world.obstacles = {block};
  RunLog log = straightFlightLog(10.0);
  const CameraRig rig(s, log, 16.0 / 9.0);
  int would_clip = 0;
  for (double t = 0.0; t <= 10.0; t += 0.25) {
    const CameraPose p = rig.pose(CameraKind::Chase, t);
    EXPECT_GT(block.signedDistance(p.eye()), 0.0) << "t = " << t;
    CameraPose wanted = p;
    wanted.distance = 20.0 * log.vehicles[0].radius;  // where it stands in open space
    would_clip += block.signedDistance(wanted.eye()) < 0.0 ? 1 : 0;
  }
  EXPECT_GT(would_clip, 0) << "the block never stood where the camera wanted to be";
}

TEST(CameraRig, UnknownCameraNameIsRejected) {
  EXPECT_THROW(cameraKind("sideways"), std::invalid_argument);
  EXPECT_EQ(cameraKind("orbit"), CameraKind::Orbit);
}

TEST(CameraRig, OverviewFramesTheWorldAndEveryStartAndGoalWithAMargin) {
  // The goal at the world's corner nearest the overview camera (the default scenario's goal sat
  // on the frame's bottom edge with the old fixed distance).
  Scenario s = renderTestScenario(320, 180);
  s.vehicles[0].waypoints = {{19, 19, 0.5}};
  RunLog log = straightFlightLog(2.0);
  log.vehicles[0].goal = {19, 19, 0.5};
  log.vehicles[0].planned_path.back() = {19, 19, 0.5};
  const WorldModel world = WorldModel::build(s);
  const RunRecord renderer_record = recordOfLog(s, log, world);
  RunRenderer renderer(s, renderer_record, 320, 180);
  std::vector<std::uint8_t> rgb;
  renderer.render(renderer.endTime(), "overview", rgb, false);
  std::vector<Eigen::Vector3d> points = {{3, 3, 2}, {19, 19, 0.5}};
  for (int c = 0; c < 8; ++c) points.emplace_back(c & 1 ? 20 : 0, c & 2 ? 20 : 0, c & 4 ? 6 : 0);
  // Projected with the camera MuJoCo rendered with: inside the frame, 5 % clear of each edge.
  double closest = 1.0;  // the smallest distance to an edge, as a fraction of the frame
  for (const Eigen::Vector3d& p : points) {
    Eigen::Vector2d px;
    ASSERT_TRUE(renderer.project(p, px));
    const double fx = px.x() / 320.0, fy = px.y() / 180.0;
    EXPECT_GE(fx, 0.05) << p.transpose();
    EXPECT_LE(fx, 0.95) << p.transpose();
    EXPECT_GE(fy, 0.05) << p.transpose();
    EXPECT_LE(fy, 0.95) << p.transpose();
    closest = std::min({closest, fx, 1 - fx, fy, 1 - fy});
  }
  // Framed from the points, not from afar: the outermost point sits at the margin.
  EXPECT_NEAR(closest, CameraRig::kOverviewMargin, 0.005);
}
