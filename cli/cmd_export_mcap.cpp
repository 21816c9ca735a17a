// cosim export-mcap RUN_DIR [--out FILE.mcap]: a logged run as an MCAP file (run/run_mcap.h)
// that Foxglove and Lichtblick open: the world, the vehicles' shapes and paths as scene
// updates, each vehicle's pose as frame transforms, its state as JSON messages for plots.
#include <iostream>

#include "cli/command.h"
#include "cli/option_checks.h"
#include "cli/run_folder.h"
#include "core/atomic_file.h"
#include "core/output_files.h"
#include "core/output_manifest.h"
#include "run/foxglove_layout.h"
#include "run/run_mcap.h"
#include "sim/world_model.h"

namespace cosim::cli {

void addExportMcapCommand(CLI::App& app, CommandContext& ctx) {
  auto* cmd = app.add_subcommand(
      "export-mcap",
      "Write a logged run (a folder of cosim run) as an MCAP file for Foxglove and Lichtblick:\n"
      "the world, vehicles and paths (foxglove.SceneUpdate), each vehicle's pose\n"
      "(foxglove.FrameTransform on /tf), its state for plots (/vehicles/<name>/state); beside\n"
      "it FILE.layout.json, a Foxglove layout (3D view of the world and vehicles, plots of\n"
      "position and error): in Foxglove, Layouts > Import from file.");
  struct Args {
    std::string dir, out;
    double rate = 100.0;
  };
  auto a = std::make_shared<Args>();
  cmd->add_option("run_dir", a->dir, "folder written by cosim run")->required();
  cmd->add_option("--out", a->out, "output file (default: RUN_DIR/run.mcap)");
  cmd->add_option("--rate", a->rate,
                  "poses and states per second and vehicle (default 100; 0: every logged sample)")
      ->check(numberIn(0.0, 100000.0));
  cmd->callback([a, &ctx] {
    const std::filesystem::path dir = a->dir;
    const Scenario s = readRunScenario(dir);
    const std::filesystem::path out =
        a->out.empty() ? dir / "run.mcap" : std::filesystem::path(a->out);
    checkOutputPath(out, a->out.empty() ? "run folder" : "--out");
    const std::filesystem::path layout = foxgloveLayoutPathFor(out);
    checkOutputPath(layout, a->out.empty() ? "run folder" : "--out");
    const RunRecord record = readRunRecord(dir, s);
    const McapExport file = runToMcap(s, record, a->rate, std::string("cosim ") + COSIM_VERSION);
    writeFileAtomically(out, file.bytes);
    writeOutputManifestOf(out, "export-mcap");  // proves the file cosim's to a later export
    std::vector<std::string> names;
    for (const auto& v : record.log.vehicles) names.push_back(v.name);
    writeFileAtomically(
        layout, foxgloveLayout(names, s.world.bounds_min, s.world.bounds_max).dump(2) + "\n");
    writeOutputManifestOf(layout, "export-mcap");
    std::cout << "written: " << out.string() << " (" << file.messages << " messages on "
              << file.channels << " channels, " << file.bytes.size() << " bytes) and "
              << layout.filename().string()
              << " beside it (a Foxglove layout: Layouts > Import from file)\n";
    ctx.status = 0;
  });
}

}  // namespace cosim::cli
