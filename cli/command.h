#pragma once
// Each cosim subcommand lives in its own file (cmd_<name>.cpp) and registers itself on the
// CLI11 app through one add*Command function declared here. A subcommand's callback stores its
// exit status (0 ok, 1 task failed, 2 bad input, 3 internal error) in `status`.
#include <CLI/CLI.hpp>

namespace cosim::cli {

struct CommandContext {
  int status = 0;
};

void addRunCommand(CLI::App& app, CommandContext& ctx);
void addPlanCommand(CLI::App& app, CommandContext& ctx);
void addBenchCommand(CLI::App& app, CommandContext& ctx);
void addRenderCommand(CLI::App& app, CommandContext& ctx);
void addReproduceCommand(CLI::App& app, CommandContext& ctx);
void addGridBenchCommand(CLI::App& app, CommandContext& ctx);
void addMapfCommand(CLI::App& app, CommandContext& ctx);
void addSweepCommand(CLI::App& app, CommandContext& ctx);
void addExportMjcfCommand(CLI::App& app, CommandContext& ctx);
void addExportMcapCommand(CLI::App& app, CommandContext& ctx);
void addPlanBenchCommand(CLI::App& app, CommandContext& ctx);
void addCompareRealCommand(CLI::App& app, CommandContext& ctx);
void addIdentifyCommand(CLI::App& app, CommandContext& ctx);

}  // namespace cosim::cli
