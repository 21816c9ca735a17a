// The scenario's render section: cameras, fixed camera, speed-up, see-through obstacles.
#include <gtest/gtest.h>

#include "core/input_error.h"
#include "sim/scenario.h"

using namespace cosim;

namespace {

std::string scenarioWithRender(const std::string& render) {
  return "world: {bounds: {min: [0, 0, 0], max: [20, 20, 6]}}\n"
         "vehicles:\n  - {name: uav1, model: quad_1500g, start: [2, 2, 2], goal: [18, 18, 2]}\n"
         "render: " +
         render + "\n";
}

std::string errorOf(const std::string& render) {
  try {
    parseScenario(scenarioWithRender(render), "r.yaml");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(RenderSettings, CamerasFixedCameraSpeedupAndAlphaAreRead) {
  const Scenario s = parseScenario(
      scenarioWithRender(
          "{camera: fixed, cameras: [chase, top, orbit], speedup: 2, obstacle_alpha: 0.5, "
          "png_frames: true, fixed_camera: {pos: [-5, 10, 8], lookat: [10, 10, 1]}}"),
      "r.yaml");
  EXPECT_EQ(s.render.camera, CameraKind::Fixed);
  EXPECT_EQ(s.render.cameras,
            (std::vector<CameraKind>{CameraKind::Chase, CameraKind::Top, CameraKind::Orbit}));
  EXPECT_DOUBLE_EQ(s.render.speedup, 2.0);
  EXPECT_DOUBLE_EQ(s.render.obstacle_alpha, 0.5);
  EXPECT_TRUE(s.render.png_frames);
  EXPECT_TRUE(s.render.has_fixed_camera);
  EXPECT_EQ(s.render.fixed_pos, Eigen::Vector3d(-5, 10, 8));
  EXPECT_EQ(s.render.fixed_lookat, Eigen::Vector3d(10, 10, 1));
}

TEST(RenderSettings, BadRenderKeysAreErrorsNamingTheKey) {
  EXPECT_NE(errorOf("{cameras: [chase, sideways]}").find("render.cameras[1]"), std::string::npos);
  EXPECT_NE(errorOf("{camera: fixed}").find("fixed_camera"), std::string::npos);
  EXPECT_NE(errorOf("{obstacle_alpha: 0}").find("render.obstacle_alpha"), std::string::npos);
  EXPECT_NE(errorOf("{speedup: -1}").find("render.speedup"), std::string::npos);
  EXPECT_NE(errorOf("{fixed_camera: {pos: [1, 1, 1], lookat: [1, 1, 1]}}").find("must differ"),
            std::string::npos);
  EXPECT_NE(errorOf("{colour: red}").find("colour"), std::string::npos);
  EXPECT_EQ(errorOf("{camera: orbit, cameras: [top]}"), "");
}

TEST(RenderSettings, SpeedIsTheTimeLapseFactorAndWinsOverItsOlderNameSpeedup) {
  EXPECT_DOUBLE_EQ(parseScenario(scenarioWithRender("{speed: 4}"), "r.yaml").render.speedup, 4.0);
  // --video-speed adds render.speed to a file that may still say speedup.
  EXPECT_DOUBLE_EQ(
      parseScenario(scenarioWithRender("{speedup: 2, speed: 8}"), "r.yaml").render.speedup, 8.0);
  EXPECT_NE(errorOf("{speed: 0}").find("render.speed"), std::string::npos);
}
