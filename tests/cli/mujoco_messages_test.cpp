// End to end: a MuJoCo warning reaches the user as one "cosim: mujoco: ..." line on stderr and
// nothing else: no "WARNING:" on stdout and no MUJOCO_LOG.TXT in the folder cosim runs in
// (MuJoCo's defaults); the run still stops as unstable and counts the warning.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "tests/support/cosim_command.h"
#include "tests/support/json_fields.h"

namespace cosim::test {
namespace {

namespace fs = std::filesystem;

TEST(MujocoMessages, AnUnstableModelWarnsOnStderrAndWritesNoLogFileIntoTheWorkingFolder) {
  const fs::path dir = freshDir("mujoco-messages");
  fs::create_directories(dir);
  // An included spring of absurd stiffness, stretched from the start: its acceleration at the
  // first step (1e15 N/m * 1 m / 1 g = 1e18 m/s^2) is far past MuJoCo's limit for a sane number.
  std::ofstream(dir / "spring.xml") << R"(<mujoco>
  <worldbody>
    <body name="spring" pos="35 3 1">
      <joint name="spring_x" type="slide" axis="1 0 0" stiffness="1e15" springref="1"/>
      <geom type="sphere" size="0.1" mass="0.001" contype="0" conaffinity="0"/>
    </body>
  </worldbody>
</mujoco>
)";
  std::ofstream(dir / "scenario.yaml")
      << "world: {bounds: {min: [0, 0, 0], max: [40, 30, 8]}, include: spring.xml}\n"
         "vehicles: [{name: uav1, model: cf2, start: [2, 2, 1], goal: [10, 10, 1]}]\n"
         "planner: {name: astar, resolution: 0.5}\n";
  const CommandResult r =
      runCosim("run scenario.yaml --no-video --no-images --quiet --out out", dir);
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_NE(r.err.find("cosim: mujoco: Nan, Inf or huge value in QACC"), std::string::npos)
      << r.err;
  EXPECT_EQ(r.out.find("WARNING"), std::string::npos) << r.out;
  EXPECT_FALSE(fs::exists(dir / "MUJOCO_LOG.TXT"));
  const std::string metrics = slurp(dir / "out" / "metrics.json");
  EXPECT_NE(metrics.find("\"fault\": \"unstable\""), std::string::npos) << metrics;
  EXPECT_EQ(jsonNumber(metrics, "mujoco_warnings"), 1.0) << metrics;
  fs::remove_all(dir);
}

}  // namespace
}  // namespace cosim::test
