// cosim plan SCENARIO.yaml: planning only, no physics. Writes path.csv, plan.json and the path
// drawn in its world (plan.png, plan.svg).
#include <cstdio>
#include <iostream>

#include "cli/command.h"
#include "cli/interrupt_flag.h"
#include "cli/planner_list.h"
#include "core/atomic_file.h"
#include "core/input_error.h"
#include "core/json_writer.h"
#include "core/output_files.h"
#include "core/output_manifest.h"
#include "core/stop_request.h"
#include "render/plan_figure.h"
#include "run/scenario_checks.h"
#include "run/scenario_planning.h"

namespace cosim::cli {

namespace {
// "44.15 m": a length as the console prints it (centimetres, not std::to_string's six decimals).
std::string lengthText(double metres) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.2f m", metres);
  return buf;
}

// path.csv, plan.json and the picture (plan.png, plan.svg) of `plan` into `dir`.
void writePlanOutputs(const Scenario& s, const VehiclePlan& plan,
                      const std::filesystem::path& dir) {
  std::string csv = "x,y,z\n";
  for (const auto& p : plan.path.waypoints) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "%.9g,%.9g,%.9g\n", p.x(), p.y(), p.z());
    csv += buf;
  }
  JsonObject j;
  j.add("success", plan.success)
      .add("status", toString(plan.status))
      .add("length_m", plan.success ? plan.path.length() : 0.0)
      .add("time_ms", plan.time_ms)
      .add("waypoints", plan.path.size())
      .add("planner", s.motion.planner.name)
      .add("inflation_m", plan.inflation)
      .add("message", plan.message)
      .add("counters", plan.counters)
      .add("params", plan.params);
  for (const auto& [k, v] : plan.counters) j.add(k, v);
  writeFileAtomically(dir / "path.csv", csv);
  writeFileAtomically(dir / "plan.json", j.str() + "\n");
  const VehicleSpec& vehicle = s.vehicles.front();
  writePlanFigure(s.world, plan.path.waypoints, vehicle.start, vehicle.goal(),
                  std::filesystem::path(s.file).filename().string() + ": " + s.motion.planner.name +
                      (plan.success ? ", " + lengthText(plan.path.length()) : ", no path"),
                  dir / "plan");
}

}  // namespace

void addPlanCommand(CLI::App& app, CommandContext& ctx) {
  auto* cmd = app.add_subcommand(
      "plan",
      "Plan the first vehicle's path in a scenario's world, without physics. Writes path.csv,\n"
      "plan.png and plan.svg (the path in its world, from above and from the side), and\n"
      "plan.json (success, status, length_m, time_ms, counters, planner, params). Exit 1 if no\n"
      "path or interrupted. `cosim plan --list` lists every planner with its parameters (name,\n"
      "default, valid values, what it does).");
  struct Args {
    std::string scenario, planner, out;
    std::vector<std::string> sets;
    bool list = false;
  };
  auto a = std::make_shared<Args>();
  cmd->add_option("scenario", a->scenario, "scenario YAML");
  cmd->add_option("--planner", a->planner, "planner name (overrides planner.name)");
  cmd->add_option("--out", a->out, "output folder (default: a new folder under out/)");
  cmd->add_option("--set", a->sets, "override a scenario key, e.g. --set planner.resolution=0.25");
  cmd->add_flag("--list", a->list,
                "list every planner with its parameters (default, valid values, meaning) and exit");
  cmd->callback([a, &ctx] {
    if (a->list) {
      std::cout << plannerListText();
      return;
    }
    if (a->scenario.empty())
      throw InputError("command line", "plan", "a scenario file is required");
    installInterruptFlag();
    // Once the scenario and its planner passed their checks (scenario_checks.h), an earlier
    // plan goes (only files cosim can prove it wrote: anything else is refused) and a new folder
    // is made if needed; bad input touches nothing.
    checkOutputDir(a->out);
    const Scenario s = loadScenarioForPlan(a->scenario, a->sets, a->planner);
    if (!a->out.empty())
      removeStaleResults(a->out, {"plan.json", "path.csv", "plan.png", "plan.svg"});
    const auto dir = prepareOutputDir(a->out, "plan");
    OutputManifestScope manifest(dir, "plan");
    const VehiclePlan plan = planFirstVehicle(s);
    for (const auto& name : plan.set_aside_params)
      std::cout << "note: the scenario's planner." << name << " does not apply to "
                << s.motion.planner.name << " (chosen by --planner or --set): set aside\n";
    // A planner ended by the stop request says so; a request that came after it returned is an
    // interrupt all the same.
    if (plan.status == PlannerStatus::Stopped || stopRequested()) {
      std::cerr << "cosim: interrupted; " << printableText(dir.string()) << " holds no plan\n";
      ctx.status = 1;
      return;
    }
    writePlanOutputs(s, plan, dir);
    manifest.finish();
    std::cout << "plan: " << printableText(dir.string()) << "\n  " << s.motion.planner.name << ": "
              << (plan.success ? "path of " + lengthText(plan.path.length())
                               : "no path (" + plan.message + ")")
              << ", " << plan.time_ms
              << " ms; picture: " << printableText((dir / "plan.png").string()) << "\n";
    ctx.status = plan.success ? 0 : 1;
  });
}

}  // namespace cosim::cli
