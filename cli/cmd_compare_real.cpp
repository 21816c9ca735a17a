// cosim compare-real RUN_DIR LOG: a real flight's log beside a cosim run of the same reference.
// Reads the run as render and export-mcap do (cli/run_folder.h) and the log (CSV or Crazyflie uSD
// binary), places the log on the run's clock (and, as --align asks, in its frame) by least
// squares, and writes compare.json, compare.md and a figure. SIGINT/SIGTERM stop it (exit 1,
// nothing written).
#include <iostream>

#include "cli/command.h"
#include "cli/interrupt_flag.h"
#include "cli/option_checks.h"
#include "cli/run_folder.h"
#include "core/input_error.h"
#include "core/output_files.h"
#include "core/output_manifest.h"
#include "experiments/compare/compare_report.h"

namespace cosim::cli {

namespace {

std::vector<std::string> threeNames(const std::string& text, const std::string& option) {
  if (text.empty()) return {};
  std::vector<std::string> names;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = text.find(',', start);
    names.push_back(
        text.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  for (const auto& n : names)
    if (n.empty() || names.size() != 3)
      throw InputError("command line", option,
                       "needs three variable names a,b,c (x, y, z), got '" + text + "'");
  return names;
}

struct CompareArgs {
  std::string run_dir, log, vehicle, out, position_vars, reference_vars;
  std::string align_to = "flown", align;
  double time_offset = 0.0;
  bool has_time_offset = false;
};

ComparisonOptions comparisonOptions(const CompareArgs& a) {
  ComparisonOptions o;
  o.align_to = a.align_to == "reference" ? AlignTo::Reference : AlignTo::Flown;
  if (!a.align.empty()) o.align = alignModeNamed(a.align);
  o.fixed_time_offset = a.has_time_offset;
  o.time_offset = a.time_offset;
  return o;
}

// Exit status: 0 compared, 1 interrupted (nothing written).
int compareReal(const CompareArgs& a) {
  // Interruptible from here on, reading included.
  const std::atomic<bool>& interrupt = installInterruptFlag();
  const auto interrupted = [] {
    std::cerr << "cosim: interrupted; nothing was written\n";
    return 1;
  };
  const std::string out_dir = a.out.empty() ? a.run_dir : a.out;
  checkOutputDir(out_dir);
  FlightLogOptions log_options;
  log_options.position_vars = threeNames(a.position_vars, "--position-vars");
  log_options.reference_vars = threeNames(a.reference_vars, "--reference-vars");
  // The run as render and export-mcap read it: the rows run.json recorded, inside its time.
  const Scenario scenario = cli::readRunScenario(a.run_dir);
  const RunFlight run =
      runFlightOf(cli::readRunRecord(a.run_dir, scenario).log, a.run_dir, a.vehicle);
  const FlightLog log = readFlightLog(a.log, log_options);
  if (interrupt.load()) return interrupted();
  std::cerr << "cosim: placing the log on the run's clock\n";
  FlightComparison c;
  try {
    c = compareFlights(run, log, comparisonOptions(a), StopToken::untimed(&interrupt));
  } catch (const AlignmentInterrupted&) {
    return interrupted();
  }
  if (interrupt.load()) return interrupted();
  const std::filesystem::path dir = prepareOutputDir(out_dir, "compare");
  // Only an earlier comparison cosim can prove it wrote is replaced (core/output_manifest.h);
  // what is written joins the folder's manifest (the run's, by default), last.
  OutputManifestScope manifest(dir, "compare-real");
  removeStaleResults(dir, {"compare.json", "compare.md", "compare.png", "compare.svg"});
  writeCompareReport(dir, CompareInputs{a.run_dir, &run, &log}, c);
  for (const std::string& w : c.warnings) std::cerr << "cosim: warning: " << w << "\n";
  manifest.finish();
  std::printf(
      "alignment %s: real RMSE %.4f m, simulated %.4f m, ratio %.3f; time offset %.4f s (%s), "
      "start offset [%.4f, %.4f, %.4f] m (%s); mean offset real - simulated [%.4f, %.4f, "
      "%.4f] m\nwritten: %s/compare.json, compare.md, compare.png, compare.svg\n",
      alignModeName(c.alignment), c.real_rmse_m, c.sim_rmse_m, c.ratio(), c.time_offset_s,
      c.time_offset_fitted ? "fitted" : "not fitted", c.start_offset_m.x(), c.start_offset_m.y(),
      c.start_offset_m.z(), c.start_offset_fitted ? "fitted" : "not fitted", c.mean_offset_m.x(),
      c.mean_offset_m.y(), c.mean_offset_m.z(), dir.string().c_str());
  return 0;
}

}  // namespace

void addCompareRealCommand(CLI::App& app, CommandContext& ctx) {
  auto* cmd = app.add_subcommand(
      "compare-real",
      "Compare a real flight's log with a cosim run of the same reference: the log (CSV with\n"
      "t,x,y,z and optional ref_x,ref_y,ref_z, or a Crazyflie uSD-card binary log) is placed on\n"
      "the run's clock by least squares (and in its frame as --align says), then both flights'\n"
      "RMSE against the run's reference over the reference's duration, at every alignment.\n"
      "Writes compare.json, compare.md, compare.png and compare.svg. See docs/compare_real.md.");
  auto a = std::make_shared<CompareArgs>();
  cmd->add_option("run_dir", a->run_dir, "folder written by cosim run")->required();
  cmd->add_option("log", a->log, "real flight log: CSV or Crazyflie uSD binary")->required();
  cmd->add_option("--vehicle", a->vehicle, "the run's vehicle to compare (needed in team runs)");
  cmd->add_option("--out", a->out, "output folder (default: RUN_DIR)");
  cmd->add_option("--position-vars", a->position_vars,
                  "uSD log: position variables x,y,z (default locSrv.x,locSrv.y,locSrv.z, else "
                  "stateEstimate.x,...)");
  cmd->add_option("--reference-vars", a->reference_vars,
                  "uSD log: reference variables x,y,z (default ctrltarget.x,ctrltarget.y,"
                  "ctrltarget.z when present)");
  cmd->add_option("--align-to", a->align_to,
                  "a log without reference is matched to the simulated flight (flown, default) "
                  "or to the run's reference")
      ->check(CLI::IsMember({"flown", "reference"}));
  cmd->add_option("--align", a->align,
                  "what is fitted and taken out of the real error: none, time, time+xy (and a "
                  "horizontal offset), time+xyz (and a 3D offset); default time, or time+xy for "
                  "a log with a reference")
      ->check(CLI::IsMember({"none", "time", "time+xy", "time+xyz"}));
  auto* time_offset = cmd->add_option("--time-offset", a->time_offset,
                                      "log time minus run time in s, instead of fitting it")
                          ->check(numberIn(-1e9, 1e9));
  cmd->callback([a, time_offset, &ctx] {
    a->has_time_offset = time_offset->count() > 0;
    ctx.status = compareReal(*a);
  });
}

}  // namespace cosim::cli
