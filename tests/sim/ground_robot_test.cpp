// Ground robots from URDF in MuJoCo: the conversion (bodies, drives, errors naming file and
// element) and short drives under the ground controllers.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "control/ground_feedback_linearization.h"
#include "control/ground_velocity_tracker.h"
#include "core/input_error.h"
#include "sim/ground_simulation.h"
#include "sim/ground_vehicle_handles.h"
#include "sim/world_model.h"
#include "tests/support/test_files.h"

namespace cosim {
namespace {

std::string scenarioText(const std::string& vehicles, const std::string& extra_world = "") {
  return "world:\n  bounds: {min: [0, 0, 0], max: [6, 6, 2]}\n" + extra_world + "vehicles:\n" +
         vehicles + "sim: {timestep: 0.002, control_rate: 50, max_time: 12}\n";
}

void writeFile(const std::filesystem::path& p, const std::string& text) {
  std::ofstream(p) << text;
}

TEST(GroundRobotModel, DiffDriveBecomesFreeBaseWithTurtleBot3WheelGeometry) {
  const Scenario s = parseScenario(
      scenarioText("  - {name: tb, model: diff_drive, start: [1, 1, 0], goal: [4, 4, 0]}\n"),
      "test.yaml");
  ASSERT_EQ(s.vehicles[0].kind, VehicleKind::GroundRobot);
  const WorldModel w = WorldModel::build(s);
  const VehicleHandles& h = w.vehicles()[0];
  EXPECT_EQ(h.kind, VehicleKind::GroundRobot);
  EXPECT_EQ(h.drive.kind, GroundDrive::Kind::Differential);
  EXPECT_FALSE(h.drive.planar_root);
  EXPECT_NEAR(h.drive.wheel_radius, 0.033, 1e-9);
  EXPECT_NEAR(h.drive.wheel_separation, 0.16, 1e-9);
  EXPECT_NEAR(h.drive.max_speed, 6.67 * 0.033, 1e-9);  // 0.22 m/s
  EXPECT_NEAR(h.params.mass, 0.825 + 2 * 0.028 + 0.005, 1e-9);
  // The chassis box's far corner (0.102, 0.07) sets the footprint radius.
  EXPECT_NEAR(h.params.radius, std::hypot(0.102, 0.07), 1e-6);
  EXPECT_EQ(w.model()->jnt_type[mj_name2id(w.model(), mjOBJ_JOINT, "tb/root")], mjJNT_FREE);
  // Two wheel servos, on the wheel joints' dofs (applied by sim/, not MuJoCo actuators).
  ASSERT_EQ(h.drive.servo_count, 2);
  const int left = mj_name2id(w.model(), mjOBJ_JOINT, "tb/left_wheel_joint");
  ASSERT_GE(left, 0);
  EXPECT_EQ(h.drive.servos[0].dof, w.model()->jnt_dofadr[left]);
  EXPECT_NEAR(h.drive.servos[0].max_speed, 6.67, 1e-9);  // rad/s, the wheel joint's <limit>
  EXPECT_EQ(w.model()->nu, 0);
}

TEST(GroundRobotModel, OmniBaseBecomesPlanarBaseFacingItsStartYaw) {
  const Scenario s = parseScenario(
      scenarioText(
          "  - {name: om, model: omni_base, start: [1, 1, 0], goal: [4, 4, 0], yaw: 90}\n"),
      "test.yaml");
  const WorldModel w = WorldModel::build(s);
  const VehicleHandles& h = w.vehicles()[0];
  EXPECT_EQ(h.drive.kind, GroundDrive::Kind::Holonomic);
  EXPECT_TRUE(h.drive.planar_root);
  EXPECT_NEAR(h.drive.max_speed, 0.6, 1e-12);
  EXPECT_NEAR(h.params.mass, 4.0, 1e-12);
  EXPECT_NEAR(h.params.radius, 0.15, 1e-9);
  EXPECT_NEAR(h.drive.start_yaw, M_PI / 2, 1e-12);
  mjData* d = mj_makeData(w.model());
  mj_resetData(w.model(), d);
  setPlanarPose(d, h, {2.5, 0.5}, 0.3);
  mj_kinematics(w.model(), d);
  const PlanarState st = readPlanarState(d, h);
  EXPECT_NEAR(st.position.x(), 2.5, 1e-12);
  EXPECT_NEAR(st.position.y(), 0.5, 1e-12);
  EXPECT_NEAR(st.yaw, 0.3, 1e-12);
  EXPECT_NEAR(d->xpos[3 * h.body], 2.5, 1e-12);  // the body really is there
  mj_deleteData(d);
}

TEST(GroundRobotModel, MalformedUrdfNamesFileAndLine) {
  const auto dir = test::makeFreshDir("ground-malformed");
  writeFile(dir / "bad.urdf", "<robot name=\"x\">\n  <link name=\"a\">\n</robot>\n");
  const Scenario s =
      parseScenario(scenarioText("  - {model: bad.urdf, start: [1, 1, 0], goal: [4, 4, 0]}\n"),
                    (dir / "s.yaml").string());
  try {
    WorldModel::build(s);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), (dir / "bad.urdf").string());
    EXPECT_NE(e.place().find("line"), std::string::npos) << e.what();
  }
  std::filesystem::remove_all(dir);
}

TEST(GroundRobotModel, UrdfJointWithUnknownLinkIsRejectedByUrdfdom) {
  const auto dir = test::makeFreshDir("ground-badjoint");
  writeFile(dir / "r.urdf",
            "<robot name=\"r\"><link name=\"base\"/><joint name=\"j\" type=\"fixed\"><parent "
            "link=\"base\"/>"
            "<child link=\"ghost\"/></joint></robot>\n");
  const Scenario s =
      parseScenario(scenarioText("  - {model: r.urdf, start: [1, 1, 0], goal: [4, 4, 0]}\n"),
                    (dir / "s.yaml").string());
  try {
    WorldModel::build(s);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), (dir / "r.urdf").string());
    EXPECT_NE(e.problem().find("ghost"), std::string::npos) << e.what();
  }
  std::filesystem::remove_all(dir);
}

TEST(GroundRobotModel, MissingMeshNamesLinkAndMeshElement) {
  const auto dir = test::makeFreshDir("ground-mesh");
  writeFile(dir / "m.urdf",
            "<robot name=\"m\"><link name=\"base\"><inertial><mass value=\"1\"/><inertia "
            "ixx=\"0.01\" ixy=\"0\" "
            "ixz=\"0\" iyy=\"0.01\" iyz=\"0\" izz=\"0.01\"/></inertial><collision><geometry>"
            "<mesh filename=\"meshes/shell.stl\"/></geometry></collision></link></robot>\n");
  const Scenario s =
      parseScenario(scenarioText("  - {model: m.urdf, start: [1, 1, 0], goal: [4, 4, 0]}\n"),
                    (dir / "s.yaml").string());
  try {
    WorldModel::build(s);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), (dir / "m.urdf").string());
    EXPECT_NE(e.place().find("link 'base' <collision>"), std::string::npos) << e.what();
    EXPECT_NE(e.place().find("shell.stl"), std::string::npos) << e.what();
    EXPECT_NE(e.problem().find("not found"), std::string::npos) << e.what();
  }
  std::filesystem::remove_all(dir);
}

// Drives one robot along a timed path and returns the log.
RunLog drive(const std::string& model, const GroundTimedPath& path, double speed,
             double yaw_deg = 0.0) {
  const Scenario s =
      parseScenario(scenarioText("  - {name: r, model: " + model + ", start: [1, 1, 0], goal: [" +
                                 std::to_string(path.points().back().x()) + ", " +
                                 std::to_string(path.points().back().y()) +
                                 ", 0], yaw: " + std::to_string(yaw_deg) + "}\n"),
                    "test.yaml");
  const WorldModel w = WorldModel::build(s);
  const VehicleHandles& h = w.vehicles()[0];
  GroundMotionLimits limits;
  limits.max_speed = h.drive.max_speed;
  limits.max_yaw_rate = h.drive.max_yaw_rate;
  std::unique_ptr<GroundController> c;
  if (h.drive.kind == GroundDrive::Kind::Holonomic)
    c = std::make_unique<GroundVelocityTracker>(limits);
  else
    c = std::make_unique<GroundFeedbackLinearization>(
        limits, GroundFeedbackLinearizationParams{0.08, 2.0, h.drive.wheel_separation});
  GroundTimedPath p = path;
  p.setSmoothing(speed / limits.max_acceleration);
  GroundPilot pilot;
  pilot.controller = c.get();
  pilot.path = &p;
  pilot.yaw = yaw_deg * M_PI / 180.0;
  pilot.goal = {path.points().back().x(), path.points().back().y(), 0.0};
  std::vector<GroundPilot> pilots{pilot};
  GroundSimOptions o;
  o.settings = s.sim;
  return simulateGround(w, s, pilots, o);
}

double maxDeviation(const RunLog& log) {
  double e = 0.0;
  for (const auto& x : log.vehicles[0].samples) {
    e = std::max(e, (x.pos - x.ref_pos).head<2>().norm());
    if (getenv("DBG"))
      printf("%.2f ref %.3f %.3f pos %.3f %.3f v %.3f %.3f cmd %.3f %.3f %.3f f %.2f %.2f\n", x.t,
             x.ref_pos.x(), x.ref_pos.y(), x.pos.x(), x.pos.y(), x.vel.x(), x.vel.y(),
             x.rotor_cmd[0], x.rotor_cmd[1], x.rotor_cmd[2], x.rotor_thrust[0], x.rotor_thrust[1]);
  }
  return e;
}

TEST(GroundRobotDrive, OmniBaseFollowsLShapedTimedPathWithinFiveCentimetres) {
  GroundTimedPath path;
  path.append(0.2, {1, 1});
  path.append(3.2, {2.2, 1});    // 0.4 m/s
  path.append(6.2, {2.2, 2.2});  // a right-angle corner
  const RunLog log = drive("omni_base", path, 0.4, 30.0);
  EXPECT_EQ(log.end_reason, RunEnd::Goal);
  ASSERT_TRUE(log.vehicles[0].reached_goal);
  EXPECT_LT(log.vehicles[0].arrival_time,
            6.6 + 0.1);  // the smoothed reference rests at 6.2 + 0.4 s
  EXPECT_LT(maxDeviation(log), 0.05);
  EXPECT_TRUE(log.vehicles[0].collisions.empty());
  // The base held its start heading of 30 degrees.
  const Eigen::Matrix3d R = log.vehicles[0].samples.back().att.toRotationMatrix();
  EXPECT_NEAR(std::atan2(R(1, 0), R(0, 0)), M_PI / 6, 0.02);
}

TEST(GroundRobotDrive, DiffDriveOnWheelsFollowsLShapedTimedPath) {
  GroundTimedPath path;
  path.append(0.2, {1, 1});
  path.append(5.2, {1.8, 1});  // 0.16 m/s
  path.append(10.2, {1.8, 1.8});
  const RunLog log = drive("diff_drive", path, 0.16);
  EXPECT_EQ(log.end_reason, RunEnd::Goal);
  ASSERT_TRUE(log.vehicles[0].reached_goal);
  // Wheels on the floor are not collisions. At the corner the robot must turn in place while
  // the reference moves on, and falls behind by up to about 0.13 m; it catches up after.
  EXPECT_TRUE(log.vehicles[0].collisions.empty());
  EXPECT_LT(maxDeviation(log), 0.15);
  EXPECT_GT(maxDeviation(log), 0.05);
  const LogSample& last = log.vehicles[0].samples.back();
  EXPECT_LT((last.pos - last.ref_pos).head<2>().norm(), 0.02);
}

TEST(GroundRobotDrive, MovingObstacleDrivenIntoRobotIsBookedAsContact) {
  // A cylinder sweeps across the resting robot's position.
  const Scenario s = parseScenario(
      scenarioText("  - {name: r, model: omni_base, start: [3, 3, 0], goal: [3, 3, 0]}\n",
                   "  moving_obstacles:\n    - {type: cylinder, radius: 0.2, height: 1, path: [[1, "
                   "3], [5, 3]], speed: 1.0}\n"),
      "test.yaml");
  const WorldModel w = WorldModel::build(s);
  GroundMotionLimits limits;
  GroundVelocityTracker c(limits);
  GroundTimedPath path;
  path.append(0.0, {3, 3});
  path.append(4.0, {3, 3});
  GroundPilot pilot;
  pilot.controller = &c;
  pilot.path = &path;
  pilot.goal = {3, 3, 0};
  std::vector<GroundPilot> pilots{pilot};
  GroundSimOptions o;
  o.settings = s.sim;
  o.settings.max_time = 3.0;
  const RunLog log = simulateGround(w, s, pilots, o);
  ASSERT_FALSE(log.vehicles[0].collisions.empty());
  EXPECT_EQ(log.vehicles[0].collisions.front().other, "moving0");
  // Contact begins when the centres are 0.35 m apart: at t = (2 - 0.35) / 1 = 1.65 s.
  EXPECT_NEAR(log.vehicles[0].collisions.front().t, 1.65, 0.05);
  ASSERT_EQ(log.moving_obstacles.size(), 1u);
  EXPECT_NEAR(log.moving_obstacles[0].pos.back().x(), 1.0 + 1.0 * log.moving_obstacles[0].t.back(),
              1e-9);
}

}  // namespace
}  // namespace cosim
