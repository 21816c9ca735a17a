#include "cli/run_folder.h"

#include <cmath>
#include <nlohmann/json.hpp>
#include <optional>

#include "control/piecewise_polynomial_reference.h"
#include "core/input_error.h"
#include "core/input_file.h"
#include "core/json_reading.h"
#include "run/run_evaluation.h"
#include "sim/run_log_io.h"
#include "sim/world_model.h"

namespace cosim::cli {

namespace {

std::string readText(const std::filesystem::path& p) {
  std::error_code ec;
  if (!std::filesystem::exists(p, ec))
    throw InputError(p.string(), "", "cannot open (is this a run folder?)");
  return readInputFile(p.string(), kMaxScenarioFileBytes, "file of a run folder");
}

// What run.json recorded: the original scenario path (relative paths in the scenario resolve
// there) and, in runs of this version on, what the logs hold (so a log cut at a line boundary is
// refused) and whether the run diverged (the only case in which a log may hold non-finite values).
struct RecordedRun {
  std::string scenario_file;
  std::optional<std::size_t> timeseries_rows, path_rows;
  bool diverged = false;
};

RecordedRun recordedRun(const std::filesystem::path& dir) {
  const std::string file = (dir / "run.json").string();
  const nlohmann::ordered_json json = parseJsonText(readText(dir / "run.json"), file);
  if (!json.is_object() || !json.contains("scenario_file") || !json["scenario_file"].is_string())
    throw InputError(file, "scenario_file", "missing");
  RecordedRun r;
  r.scenario_file = json["scenario_file"].get<std::string>();
  const auto count = [&](const char* key) -> std::optional<std::size_t> {
    if (!json.contains(key)) return std::nullopt;
    if (!json[key].is_number_unsigned()) throw InputError(file, key, "not a row count");
    return json[key].get<std::size_t>();
  };
  r.timeseries_rows = count("timeseries_rows");
  r.path_rows = count("path_rows");
  const std::optional<RunEnd> end = runEndNamed(json.value("end_reason", std::string()));
  r.diverged = end == RunEnd::Diverged || end == RunEnd::Unstable;
  return r;
}

// What the run could have logged: the scenario bounds the log it is read back from.
LogBounds logBoundsFor(const Scenario& s) {
  LogBounds b;
  // The last sample may fall a control period after max_time; a second is ample.
  b.max_time = s.sim.max_time + 1.0;
  b.max_rows_per_vehicle = static_cast<std::size_t>(std::ceil(b.max_time * s.sim.control_rate)) + 2;
  b.max_vehicles = s.vehicles.size();
  b.max_moving_obstacles = s.moving_obstacles.size();
  b.max_path_points = 20000000;
  return b;
}

RunLog readRunLog(const std::filesystem::path& dir, const Scenario& scenario) {
  RunLog log;
  // The time series first: it names the vehicles, and a single vehicle's path.csv has no
  // vehicle column (its rows belong to the first vehicle).
  const RecordedRun recorded = recordedRun(dir);
  LogBounds bounds = logBoundsFor(scenario);
  bounds.timeseries_rows = recorded.timeseries_rows;
  bounds.path_rows = recorded.path_rows;
  bounds.non_finite_allowed = recorded.diverged;
  readTimeseriesCsv((dir / "timeseries.csv").string(), log, bounds);
  readPathCsv((dir / "path.csv").string(), log, bounds);
  // Where the moving obstacles were (without it they would stand at their start); runs
  // logged before the file existed have none.
  if (!scenario.moving_obstacles.empty() && std::filesystem::exists(dir / "moving_obstacles.csv"))
    readMovingObstaclesCsv((dir / "moving_obstacles.csv").string(), log, bounds);
  return log;
}

// What the files do not hold, from the scenario and its composed world.
void completeRunLog(RunLog& log, const Scenario& scenario, const WorldModel& world) {
  for (std::size_t v = 0; v < log.vehicles.size() && v < scenario.vehicles.size(); ++v) {
    log.vehicles[v].goal = scenario.vehicles[v].goal();
    log.vehicles[v].radius = world.vehicles()[v].params.radius;
    if (scenario.vehicles[v].reference)  // its tracking error covers the reference's duration
      log.vehicles[v].reference_end = scenario.vehicles[v].reference->duration();
    if (scenario.vehicles[v].kind == VehicleKind::Quadrotor)
      log.vehicles[v].max_thrust = world.vehicles()[v].params.max_thrust;
  }
}

}  // namespace

Scenario readRunScenario(const std::filesystem::path& dir) {
  const std::filesystem::path file = dir / "scenario.yaml";
  const std::string yaml = readText(file);
  // Its errors name this file, whose lines they count; its relative paths were written for the
  // original's folder; its references are the copies the run kept here.
  const std::filesystem::path original = recordedRun(dir).scenario_file;
  return parseRunFolderScenario(yaml, file.string(), original.parent_path(), dir);
}

RunRecord readRunRecord(const std::filesystem::path& dir, const Scenario& scenario) {
  RunRecord record;
  record.log = readRunLog(dir, scenario);
  record.world = std::make_shared<const WorldModel>(WorldModel::build(scenario));
  completeRunLog(record.log, scenario, *record.world);
  record.setup = resolveRun(scenario, false);
  trackVehicles(record.setup, record.log, record.metrics);
  return record;
}

}  // namespace cosim::cli
