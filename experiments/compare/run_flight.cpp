#include "experiments/compare/run_flight.h"

#include <yaml-cpp/yaml.h>

#include <cstdio>

#include "core/input_error.h"
#include "core/input_file.h"
#include "sim/yaml_document.h"

namespace cosim {

namespace {

// A reference sample differs from another when it is further apart than this (m): the time
// series is written with 9 significant digits.
constexpr double kStillTolerance = 1e-7;

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
  if (first == r.size())
    throw InputError(f.timeseries_file, "vehicle " + f.vehicle,
                     "the reference never moves (a hover): there is no flight along it to "
                     "compare, and no motion by which to place a log in time");
  f.window_begin = first;
  f.window_end = last + 1;
}

void requireFlightPositions(const RunFlight& f) {
  for (const SampledPath* path : {&f.reference, &f.flown})
    for (std::size_t k = 0; k < path->size(); ++k)
      if (!path->p[k].allFinite() || path->p[k].cwiseAbs().maxCoeff() > kMaxFlightCoordinateM) {
        char place[96];
        std::snprintf(place, sizeof place, "vehicle %s, t = %.6g s", f.vehicle.c_str(), path->t[k]);
        char what[160];
        std::snprintf(what, sizeof what,
                      "%s position [%.6g, %.6g, %.6g] m is not finite or beyond %.0e m",
                      path == &f.reference ? "reference" : "flown", path->p[k].x(), path->p[k].y(),
                      path->p[k].z(), kMaxFlightCoordinateM);
        throw InputError(f.timeseries_file, place, what);
      }
}

}  // namespace

RunFlight runFlightOf(const RunLog& log, const std::filesystem::path& run_dir,
                      const std::string& vehicle) {
  const std::filesystem::path series = run_dir / "timeseries.csv",
                              scenario = run_dir / "scenario.yaml";
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
  requireFlightPositions(f);
  findWindow(f);
  f.relative_reference = relativeReference(scenario, v.name);
  return f;
}

}  // namespace cosim
