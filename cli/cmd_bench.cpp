// cosim bench: built-in performance figures, each section comparing two things in one run.
#include <cstdio>
#include <iostream>

#include "cli/command.h"
#include "core/input_error.h"
#include "core/json_writer.h"
#include "experiments/bench/ant_planners.h"
#include "experiments/bench/bench_section.h"
#include "experiments/bench/grid_astar_vs_boost.h"
#include "experiments/bench/mapf_planners.h"
#include "experiments/bench/physics_loop.h"
#include "experiments/bench/reference_flight.h"
#include "experiments/bench/render_pipeline.h"
#include "experiments/bench/sweep_throughput.h"
#include "experiments/bench/team_figures.h"
#include "experiments/bench/team_render.h"
#include "experiments/bench/team_scale.h"
#include "experiments/bench/trajectory_generation.h"

namespace cosim::cli {

namespace {
// The sections, in the order they run.
struct NamedSection {
  const char* name;
  bench::SectionFunction run;
};
const std::vector<NamedSection>& sections() {
  static const std::vector<NamedSection> list = {
      {"physics_loop", bench::benchPhysicsLoop},
      {"sensing_loop", bench::benchSensingLoop},
      {"reference_flight", bench::benchReferenceFlight},
      {"team_scale", bench::benchTeamScale},
      {"render_pipeline", bench::benchRenderPipeline},
      {"team_render", bench::benchTeamRender},
      {"team_figures", bench::benchTeamFigures},
      {"trajectory_generation", bench::benchTrajectoryGeneration},
      {"mapf_planners", bench::benchMapfPlanners},
      {"ant_planners", bench::benchAntPlanners},
      {"grid_astar_vs_boost", bench::benchGridAStarVsBoost},
      {"sweep_throughput", bench::benchSweepThroughput},
  };
  return list;
}
}  // namespace

void addBenchCommand(CLI::App& app, CommandContext& ctx) {
  auto* cmd = app.add_subcommand(
      "bench",
      "Built-in performance figures. Each section measures ours against a peer or the bare\n"
      "engine in the same run and reports the ratio.");
  struct Args {
    bool json = false, quick = false;
    std::vector<std::string> only;
  };
  auto a = std::make_shared<Args>();
  cmd->add_flag("--json", a->json, "print JSON instead of a table");
  cmd->add_flag("--quick", a->quick, "small workloads (a smoke test, not a measurement)");
  cmd->add_option("--section", a->only, "run only these sections (repeatable)");
  cmd->callback([a, &ctx] {
    for (const auto& name : a->only) {
      bool known = false;
      for (const auto& s : sections()) known = known || name == s.name;
      if (!known) throw InputError("command line", "--section", "unknown section '" + name + "'");
    }
    std::vector<JsonObject> results;
    for (const auto& s : sections()) {
      if (!a->only.empty() && std::find(a->only.begin(), a->only.end(), s.name) == a->only.end())
        continue;
      if (!a->json) std::cerr << "cosim: bench " << s.name << "..." << std::endl;
      const bench::Section r = s.run(a->quick);
      if (a->json) {
        JsonObject j;
        j.add("section", r.name).add("note", r.note);
        std::map<std::string, double> figures;
        for (const auto& f : r.figures) figures[f.name] = f.value;
        j.add("figures", figures);
        results.push_back(j);
      } else {
        std::printf("%s\n", r.name.c_str());
        for (const auto& f : r.figures)
          std::printf("  %-40s %14.4g %s\n", f.name.c_str(), f.value, f.unit.c_str());
        if (!r.table.empty()) std::printf("%s", r.table.c_str());
        std::printf("  %s\n\n", r.note.c_str());
      }
    }
    if (a->json) std::cout << JsonObject().addArray("sections", results).str() << "\n";
    ctx.status = 0;
  });
}

}  // namespace cosim::cli
