#include "experiments/compare/run_flight.h"

#include <yaml-cpp/yaml.h>

#include "core/input_error.h"
#include "core/input_file.h"
#include "sim/run_log_io.h"
#include "sim/yaml_document.h"

namespace cosim {

namespace {

// A reference sample differs from another when it is further apart than this (m): the time
// series is written with 9 significant digits.
constexpr double kStillTolerance = 1e-7;

void requireFile(const std::filesystem::path& p) {
  std::error_code ec;
  if (!std::filesystem::exists(p, ec))
    throw InputError(p.string(), "", "missing (is this a folder written by cosim run?)");
}

// vehicles[i].reference.relative of the vehicle named `name` in the scenario the run saved
// (read as a document, not loaded: only this key matters here). A vehicle without a name is
// "uav<i+1>", as the scenario loader names it.
bool relativeReference(const std::filesystem::path& scenario_file, const std::string& name) {
  const std::string file = scenario_file.string();
  const YAML::Node root =
      loadYamlDocument(readInputFile(file, kMaxScenarioFileBytes, "scenario file"), file);
  if (!root.IsMap() || !root["vehicles"] || !root["vehicles"].IsSequence()) return false;
  std::size_t index = root["vehicles"].size();
  for (std::size_t i = 0; i < root["vehicles"].size(); ++i) {
    if (!root["vehicles"][i].IsMap()) continue;
    const YAML::Node n = root["vehicles"][i]["name"];
    const std::string own = n && n.IsScalar() ? n.Scalar() : "uav" + std::to_string(i + 1);
    if (own == name) index = i;
  }
  if (index == root["vehicles"].size()) return false;
  const YAML::Node ref = root["vehicles"][index]["reference"];
  if (!ref || !ref.IsMap() || !ref["relative"]) return false;
  try {
    return ref["relative"].as<bool>();
  } catch (const YAML::Exception&) {
    throw InputError(file, "vehicles[" + std::to_string(index) + "].reference.relative",
                     "not true or false");
  }
}

void findWindow(RunFlight& f) {
  const auto& r = f.reference.p;
  std::size_t first = r.size(), last = 0;
  for (std::size_t k = 1; k < r.size(); ++k) {
    if ((r[k] - r[k - 1]).norm() <= kStillTolerance) continue;
    if (first == r.size()) first = k - 1;
    last = k;
  }
  if (first == r.size()) {  // never moves
    f.window_begin = 0;
    f.window_end = r.size();
  } else {
    f.window_begin = first;
    f.window_end = last + 1;
  }
}

}  // namespace

RunFlight readRunFlight(const std::filesystem::path& run_dir, const std::string& vehicle) {
  const std::filesystem::path series = run_dir / "timeseries.csv",
                              scenario = run_dir / "scenario.yaml";
  requireFile(scenario);
  requireFile(series);
  RunLog log;
  readTimeseriesCsv(series.string(), log);
  if (log.vehicles.empty()) throw InputError(series.string(), "", "no samples");
  std::string names;
  std::size_t index = log.vehicles.size();
  for (std::size_t i = 0; i < log.vehicles.size(); ++i) {
    names += (i ? ", " : "") + log.vehicles[i].name;
    if (log.vehicles[i].name == vehicle) index = i;
  }
  if (vehicle.empty() && log.vehicles.size() == 1) index = 0;
  if (vehicle.empty() && log.vehicles.size() > 1)
    throw InputError("command line", "--vehicle",
                     "the run has several vehicles (" + names + "): name one");
  if (index == log.vehicles.size())
    throw InputError("command line", "--vehicle",
                     "no vehicle '" + vehicle + "' in the run (it has " + names + ")");
  const VehicleLog& v = log.vehicles[index];
  if (v.samples.size() < 2) throw InputError(series.string(), v.name, "fewer than 2 samples");
  RunFlight f;
  f.vehicle = v.name;
  f.timeseries_file = series.string();
  for (const LogSample& s : v.samples) {
    if (!f.reference.t.empty() && s.t <= f.reference.t.back()) continue;  // repeated time
    f.reference.t.push_back(s.t);
    f.reference.p.push_back(s.ref_pos);
    f.flown.t.push_back(s.t);
    f.flown.p.push_back(s.pos);
  }
  findWindow(f);
  f.relative_reference = relativeReference(scenario, v.name);
  return f;
}

}  // namespace cosim
