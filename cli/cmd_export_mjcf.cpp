// cosim export-mjcf SCENARIO.yaml [--out FILE.xml]: the world a run would simulate (obstacles,
// grid-map boxes, included MJCF, every vehicle with its prefixed names, rotor constants) as one
// standalone MJCF file that MuJoCo's own tools load: mujoco-compile, mujoco-testspeed (the
// engine's speed on this very model, the limit a simulation loop is measured against) and
// mujoco-simulate. The rotors' dynamics and the air are cosim's, not the file's: its thrust
// actuators take the rotor thrust directly, so in MuJoCo's viewer the vehicles fall unless
// driven.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "cli/command.h"
#include "core/atomic_file.h"
#include "core/input_error.h"
#include "core/output_files.h"
#include "core/output_manifest.h"
#include "core/temporary_name.h"
#include "sim/world_model.h"

namespace cosim::cli {

void addExportMjcfCommand(CLI::App& app, CommandContext& ctx) {
  auto* cmd = app.add_subcommand(
      "export-mjcf",
      "Write the scenario's composed world as one standalone MJCF file (loads in mujoco-compile,\n"
      "mujoco-testspeed and mujoco-simulate).");
  struct Args {
    std::string scenario, out;
    std::vector<std::string> sets;
  };
  auto a = std::make_shared<Args>();
  cmd->add_option("scenario", a->scenario, "scenario YAML")->required();
  cmd->add_option("--out", a->out,
                  "output file (default: <scenario name>.xml in the current folder)");
  cmd->add_option("--set", a->sets, "override a scenario key, e.g. --set render.width=1920");
  cmd->callback([a, &ctx] {
    const std::filesystem::path out =
        a->out.empty()
            ? std::filesystem::path(std::filesystem::path(a->scenario).stem().string() + ".xml")
            : std::filesystem::path(a->out);
    // Before any work: a folder, a FIFO or a device there, or no folder to write into.
    checkOutputPath(out, a->out.empty() ? "output file" : "--out");
    const Scenario s = loadScenario(a->scenario, a->sets);
    const std::filesystem::path dir = out.parent_path().empty() ? "." : out.parent_path();
    const WorldModel world = WorldModel::build(s);  // compiles it: MuJoCo keeps its last XML
    // MuJoCo writes the file itself (following whatever is at the name it is given): into a new
    // folder of cosim's own under a temporary name, then read back and written in place
    // atomically like every other output.
    const std::filesystem::path work = createTemporaryFolder(dir / out.filename(), ".mjcf");
    const std::filesystem::path tmp = work / "model.xml";
    char error[1024] = "";
    const bool saved = mj_saveLastXML(tmp.c_str(), world.model(), error, sizeof error);
    std::ifstream in(tmp);
    std::ostringstream text;
    text << "<!-- Composed by cosim from " << s.file << " (cosim export-mjcf). -->\n" << in.rdbuf();
    in.close();
    std::error_code ignored;
    std::filesystem::remove_all(work, ignored);
    if (!saved) throw std::runtime_error("mujoco could not write the model: " + std::string(error));
    writeFileAtomically(out, text.str());
    writeOutputManifestOf(out, "export-mjcf");  // proves the file cosim's to a later export
    std::cout << "written: " << out.string() << " (" << world.model()->nbody << " bodies, "
              << world.model()->ngeom << " geoms, " << world.model()->nu << " actuators, "
              << world.model()->nv << " degrees of freedom)\n";
    ctx.status = 0;
  });
}

}  // namespace cosim::cli
