// cosim: plan, fly, evaluate and render. See README.md and docs/commands.md.
#include <csignal>
#include <cstdio>
#include <exception>
#include <iostream>

#include "cli/command.h"
#include "core/input_error.h"
#include "core/stop_requested_error.h"
#include "sim/mujoco_messages.h"

int main(int argc, char** argv) {
  // A write to a pipe whose reader died (ffmpeg, gnuplot) is an ordinary error the writer
  // reports, not a silent death of the whole program by SIGPIPE.
  std::signal(SIGPIPE, SIG_IGN);
  cosim::installMujocoMessageHandlers();
  CLI::App app{
      "cosim: a physics-backed co-simulator for UAVs and ground robots.\n"
      "Plans paths in 2D/3D obstacle worlds, turns them into trajectories, flies them in MuJoCo\n"
      "under feedback control, evaluates tracking and clearance, and renders videos off-screen."};
  app.set_version_flag("--version", std::string("cosim ") + COSIM_VERSION);
  app.require_subcommand(1);
  cosim::cli::CommandContext ctx;
  cosim::cli::addRunCommand(app, ctx);
  cosim::cli::addPlanCommand(app, ctx);
  cosim::cli::addRenderCommand(app, ctx);
  cosim::cli::addBenchCommand(app, ctx);
  cosim::cli::addReproduceCommand(app, ctx);
  cosim::cli::addGridBenchCommand(app, ctx);
  cosim::cli::addMapfCommand(app, ctx);
  cosim::cli::addSweepCommand(app, ctx);
  cosim::cli::addExportMjcfCommand(app, ctx);
  cosim::cli::addExportMcapCommand(app, ctx);
  cosim::cli::addPlanBenchCommand(app, ctx);
  cosim::cli::addCompareRealCommand(app, ctx);
  cosim::cli::addIdentifyCommand(app, ctx);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help and --version are "errors" with exit code 0 in CLI11.
    if (e.get_exit_code() == 0) return app.exit(e);
    // Bad usage is bad input: one line, like every other (CLI11 adds a second).
    std::cerr << "cosim: command line: " << cosim::printableText(e.what())
              << " (see cosim --help)\n";
    return 2;
  } catch (const cosim::InputError& e) {
    std::cerr << "cosim: " << e.what() << "\n";
    return 2;
  } catch (const cosim::StopRequestedError&) {
    // A stage a command does not end itself (a chart's gnuplot killed midway): nothing of it
    // was published.
    std::cerr << "cosim: interrupted\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "cosim: internal error: " << cosim::printableText(e.what()) << "\n";
    return 3;
  }
  return ctx.status;
}
