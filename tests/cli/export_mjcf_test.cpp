// cosim export-mjcf writes the world a run simulates as one standalone MJCF file: MuJoCo loads
// it on its own (as mujoco-compile and mujoco-testspeed would) into the same model.
#include <gtest/gtest.h>
#include <mujoco/mujoco.h>

#include "sim/world_model.h"
#include "tests/support/cosim_command.h"

namespace cosim::test {
namespace {

TEST(ExportMjcf, TheWrittenFileLoadsIntoTheModelARunSimulates) {
  const std::filesystem::path dir = freshDir("export-mjcf");
  std::filesystem::create_directories(dir);
  const std::string scenario =
      std::string(COSIM_SOURCE_DIR) + "/experiments/scenarios/ground_team_with_uavs.yaml";
  const CommandResult r = runCosim("export-mjcf " + scenario + " --out " + (dir / "w.xml").string());
  ASSERT_EQ(r.status, 0) << r.err;
  char error[1000] = "";
  mjModel* m = mj_loadXML((dir / "w.xml").c_str(), nullptr, error, sizeof error);
  ASSERT_NE(m, nullptr) << error;
  const WorldModel world = WorldModel::build(loadScenario(scenario));
  EXPECT_EQ(m->nbody, world.model()->nbody);
  EXPECT_EQ(m->ngeom, world.model()->ngeom);
  EXPECT_EQ(m->nv, world.model()->nv);
  EXPECT_EQ(m->nu, 0);  // the rotors and servos are cosim's
  EXPECT_EQ(m->nnumeric, world.model()->nnumeric);
  mj_deleteModel(m);
  std::filesystem::remove_all(dir);
}

TEST(ExportMjcf, AMissingOutputFolderIsBadInputAndWritesNothing) {
  const std::string scenario = std::string(COSIM_SOURCE_DIR) + "/experiments/scenarios/default.yaml";
  const CommandResult r = runCosim("export-mjcf " + scenario + " --out /nonexistent/dir/w.xml");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "cosim: /nonexistent/dir/w.xml: --out: folder /nonexistent/dir does not exist\n");
}

}  // namespace
}  // namespace cosim::test
