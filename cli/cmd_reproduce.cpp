// cosim reproduce NAME: re-runs one of the seed documents' experiments and writes a markdown
// table with the seed's published numbers beside ours.
#include <chrono>
#include <iostream>

#include "cli/command.h"
#include "cli/option_checks.h"
#include "core/input_error.h"
#include "core/output_files.h"
#include "core/output_manifest.h"
#include "experiments/reproduce/report_files.h"

namespace cosim::reproduce {
// One declaration per reproduction (each defined in experiments/reproduce/<name>.cpp).
Report seed003Discrete(const Options& options);
Report seed003Sampling(const Options& options);
Report seed002AntVsGa(const Options& options);
Report seed002Maklink(const Options& options);
Report seed004Planners(const Options& options);
Report seed004WhcaWindow(const Options& options);
Report seed004MapfScaling(const Options& options);
Report seed000Msac(const Options& options);
Report seed000Sacodm(const Options& options);
Report seed000Rna(const Options& options);
Report seed003Flight(const Options& options);
Report trackingAcceptance(const Options& options);
Report controllerStudy(const Options& options);
Report crazyflieFigure8(const Options& options);
}  // namespace cosim::reproduce

namespace cosim::cli {

namespace {
// The reproductions, by name.
const std::vector<reproduce::Entry>& reproductions() {
  static const std::vector<reproduce::Entry> entries = {
      {"controller-study",
       "realism: figure-eight at rising speed, rotor drag, model error, mocap + EKF; geometric, "
       "geometric_drag, indi, indi_drag, dsl_pid (Sun et al. 2022)",
       reproduce::controllerStudy},
      {"crazyflie-figure8",
       "Crazyflie 2.1 Brushless on Crazyswarm2's figure-eight at timescales 1.0-0.5: predicted "
       "RMSE per firmware controller, and each effect's share",
       reproduce::crazyflieFigure8},
      {"tracking",
       "tracking acceptance: every bundled 3D world, quad_1500g at 3 m/s and cf2 at 1 m/s, "
       "tracking errors",
       reproduce::trackingAcceptance},
      {"seed003-flight",
       "Navratil 2019 Sec. 4.2: Theta* and RRT*FN on map 3, the thesis's pipeline and ours, in "
       "MuJoCo",
       reproduce::seed003Flight},
      {"seed000-msac", "Pencik 2014 Tabs. 6.1-6.7: MSAC tabu tables, post-processing, ants, MAX",
       reproduce::seed000Msac},
      {"seed000-sacodm",
       "Pencik 2014 Tabs. 6.8-6.16, Fig. 6.5: SACO vs SACOdm, gamma, AS/EAS, ants",
       reproduce::seed000Sacodm},
      {"seed000-rna", "Pencik 2014 Figs. 6.6-6.9: RNA, WF-RNA vs D* Lite, sight, moving obstacles",
       reproduce::seed000Rna},
      {"seed004-planners",
       "Szulc 2018 §6.3: LRA* vs CA* vs WHCA* (and CBS) on maze, open, bottleneck",
       reproduce::seed004Planners},
      {"seed004-whca-window",
       "Szulc 2018 §6.3: WHCA* over window sizes, fixed vs dynamic priorities",
       reproduce::seed004WhcaWindow},
      {"seed004-mapf-scaling", "WHCA* and CBS success and SOC vs agents on the MAPF benchmarks",
       reproduce::seed004MapfScaling},
      {"seed003-sampling",
       "Navratil 2019 Tabs. 4-17: RRT vs RRT* (thesis, Karaman-Frazzoli) vs RRT*FN, 2D and 3D maps",
       reproduce::seed003Sampling},
      {"seed003-discrete",
       "Navratil 2019 Tabs. 1-4: A* vs Basic Theta* vs Lazy Theta*, 2D and 3D maps",
       reproduce::seed003Discrete},
      {"seed002-ant-vs-ga",
       "the ant-algorithm lecture, part A: grid ant algorithm vs GA on three workspaces",
       reproduce::seed002AntVsGa},
      {"seed002-maklink",
       "the ant-algorithm lecture, part B: MAKLINK graph, Dijkstra, ACS offsets vs real-coded GA",
       reproduce::seed002Maklink},
  };
  return entries;
}
}  // namespace

void addReproduceCommand(CLI::App& app, CommandContext& ctx) {
  auto* cmd = app.add_subcommand("reproduce",
                                 "Re-run an experiment of the seed theses; writes NAME.md with the "
                                 "seed's numbers beside ours, and NAME.json");
  struct Args {
    std::string name, out;
    int runs = 0;
    std::uint64_t seed = 1;
    bool quick = false, list = false;
  };
  auto args = std::make_shared<Args>();
  cmd->add_option("name", args->name, "which experiment (see --list)");
  cmd->add_option("--runs", args->runs, "repetitions per configuration (default: the seed's)")
      ->check(wholeNumberIn(0, 1000000000));
  cmd->add_option("--seed", args->seed, "base random seed (run i uses seed + i)")
      ->check(seedNumber());
  cmd->add_option("--out", args->out, "output folder (default: a new folder under out/)");
  cmd->add_flag("--quick", args->quick, "a small version, for smoke tests");
  cmd->add_flag("--list", args->list, "list the available experiments");
  cmd->callback([args, &ctx] {
    if (args->list || args->name.empty()) {
      for (const auto& e : reproductions()) std::cout << e.name << "\t" << e.description << "\n";
      if (!args->list) throw InputError("command line", "reproduce", "name an experiment");
      return;
    }
    for (const auto& e : reproductions()) {
      if (args->name != e.name) continue;
      reproduce::Options opt;
      opt.runs = args->runs;
      opt.seed = args->seed;
      opt.quick = args->quick;
      opt.out_dir = prepareOutputDir(args->out, args->name).string();
      // The files of an experiment start with its name: an earlier run's are replaced only if
      // cosim can prove it wrote them (core/output_manifest.h), checked before any work. What is
      // written is recorded in the folder's manifest, last.
      for (const auto& p : matchingOutputs(opt.out_dir, {args->name + "*"}))
        requireCosimOutput(p, "--out");
      OutputManifestScope manifest(opt.out_dir, "reproduce");
      const auto started = std::chrono::steady_clock::now();
      reproduce::Report result = e.run(opt);
      result.run_time_s =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
      const std::string report = reproduce::writeReportFiles(args->name, opt, result);
      manifest.finish();
      std::cout << report << "\nwritten: " << opt.out_dir << "/" << args->name << ".md and "
                << args->name << ".json\n";
      ctx.status = 0;
      return;
    }
    throw InputError("command line", "reproduce",
                     "unknown experiment '" + args->name + "' (see cosim reproduce --list)");
  });
}

}  // namespace cosim::cli
