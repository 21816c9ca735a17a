// The chase camera over the default run's whole flight: never inside an obstacle, never behind
// one (nothing between it and the vehicle), always over the world's floor, and the top of its
// frame shows floor rather than the sky beyond the world's edge; the vehicle stays in view, clear
// of the legend.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "render/camera_occlusion.h"
#include "render/camera_rig.h"
#include "render/log_lookup.h"
#include "tests/run/headless_run.h"

namespace cosim {
namespace {

// Where the ray through the top centre of the frame (45 degree lens) meets the floor plane;
// false when it points at or above the horizon.
bool topOfFrameOnFloor(const CameraPose& p, double floor_z, Eigen::Vector3d& hit) {
  const double a = p.azimuth * M_PI / 180.0, top = (p.elevation + 22.5) * M_PI / 180.0;
  if (top >= 0.0) return false;
  const Eigen::Vector3d eye = p.eye();
  const Eigen::Vector3d ray(std::cos(top) * std::cos(a), std::cos(top) * std::sin(a),
                            std::sin(top));
  hit = eye + ray * ((eye.z() - floor_z) / -ray.z());
  return true;
}

TEST(ChaseCamera, DefaultRunIsNeverFilmedFromInsideOrBehindAnObstacleOrBeyondTheWorld) {
  const std::filesystem::path file =
      std::filesystem::path(COSIM_SOURCE_DIR) / "experiments/scenarios/default.yaml";
  Scenario s = loadScenario(file.string());
  std::string metrics;
  const RunRecord run = test::runWithoutPictures(s, "chase-default", metrics);
  ASSERT_FALSE(run.log.vehicles.empty());
  const VehicleLog& v = run.log.vehicles.front();
  const CameraRig rig(s, run.log, 16.0 / 9.0);
  const Eigen::Vector3d lo = s.world.bounds_min, hi = s.world.bounds_max;
  const double end = logEndTime(run.log);
  int frames = 0;
  for (double t = 0.0; t <= end; t += 0.5, ++frames) {
    const CameraPose p = rig.pose(CameraKind::Chase, t);
    const Eigen::Vector3d eye = p.eye(), vehicle = v.samples[sampleIndexAt(v, t)].pos;
    EXPECT_TRUE(overFloor(eye, lo, hi)) << "t = " << t << ": eye " << eye.transpose();
    for (const Obstacle& o : s.world.obstacles)
      EXPECT_GT(o.signedDistance(eye), 0.0) << "t = " << t << ": eye inside an obstacle";
    EXPECT_EQ(firstObstacleHit(s.world.obstacles, vehicle, eye, 0.0), 1.0)
        << "t = " << t << ": an obstacle between the vehicle and the camera";
    // A tenth of the world's size beyond its edge may show; the sky above it may not.
    Eigen::Vector3d hit;
    ASSERT_TRUE(topOfFrameOnFloor(p, lo.z(), hit)) << "t = " << t << ": horizon in view";
    const double margin = 0.1 * (hi - lo).head<2>().norm();
    EXPECT_TRUE(overFloor(hit, lo - Eigen::Vector3d::Constant(margin),
                          hi + Eigen::Vector3d::Constant(margin)))
        << "t = " << t << ": the top of the frame looks past the world's edge at "
        << hit.transpose();
    // The vehicle is in the frame, clear of the legend (bottom left), the colour scale (bottom
    // right) and the edges: steep views from close by used to put it half under the legend.
    Eigen::Vector2d uv;
    ASSERT_TRUE(frameCoordinates(p, vehicle, 16.0 / 9.0, uv)) << "t = " << t << ": behind";
    EXPECT_TRUE(ChaseVehicleZone::contains(uv))
        << "t = " << t << ": the vehicle at " << uv.transpose() << " in the frame";
  }
  EXPECT_GT(frames, 40);  // the default flight lasts about 30 s
}

TEST(ChaseCamera, SphereTracingFindsTheFirstWallOnASegment) {
  Obstacle wall;
  wall.type = ObstacleType::Box;
  wall.pos = {5, 0, 1};
  wall.size = {1, 4, 2};  // x from 4.5 to 5.5
  const std::vector<Obstacle> world = {wall};
  EXPECT_NEAR(firstObstacleHit(world, {0, 0, 1}, {10, 0, 1}, 0.0), 0.45, 1e-3);
  EXPECT_NEAR(firstObstacleHit(world, {0, 0, 1}, {10, 0, 1}, 0.5), 0.40, 1e-3);
  EXPECT_EQ(firstObstacleHit(world, {0, 0, 1}, {4, 0, 1}, 0.0), 1.0);   // stops short of it
  EXPECT_EQ(firstObstacleHit(world, {0, 3, 1}, {10, 3, 1}, 0.0), 1.0);  // passes beside it
}

}  // namespace
}  // namespace cosim
