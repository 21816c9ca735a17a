// A Crazyflie uSD log as a flight log: the position (and reference) variables picked by name.
#include <cmath>
#include <sstream>

#include "core/input_error.h"
#include "experiments/compare/flight_log.h"
#include "experiments/compare/usd_log_reader.h"

namespace cosim {

namespace {

const std::vector<std::string> kMocapPosition = {"locSrv.x", "locSrv.y", "locSrv.z"};
const std::vector<std::string> kEstimatePosition = {"stateEstimate.x", "stateEstimate.y",
                                                    "stateEstimate.z"};
const std::vector<std::string> kSetpoint = {"ctrltarget.x", "ctrltarget.y", "ctrltarget.z"};

std::string joined(const std::vector<std::string>& names) {
  std::string s;
  for (const auto& n : names) s += (s.empty() ? "" : ",") + n;
  return s;
}

// What the log holds, for a message that says why nothing fitted: "event: var, var; ...".
std::string contents(const UsdLog& log) {
  std::ostringstream s;
  std::size_t shown = 0;
  for (const UsdEventType& t : log.eventTypes()) {
    s << (shown ? "; " : "") << t.name << ":";
    for (const UsdVariable& v : t.variables) {
      if (++shown > 24) return s.str() + " ...";
      s << " " << v.name;
    }
  }
  return shown ? s.str() : "no variables";
}

// The series of three variables, times strictly increasing: a record stamped like the one
// before it (millisecond stamps of version 1 at rates near 1 kHz) is left out; a time going
// back is an error at its record.
SampledPath readPath(const UsdLog& log, int type, const std::vector<std::string>& names,
                     const std::string& file) {
  const UsdSeries s = log.series(static_cast<std::size_t>(type), names);
  SampledPath path;
  for (std::size_t k = 0; k < s.t.size(); ++k) {
    const std::string place = "byte " + std::to_string(s.record_byte[k]);
    if (!path.t.empty() && s.t[k] < path.t.back())
      throw InputError(file, place, "time goes back in event " + log.eventTypes()[type].name);
    const Eigen::Vector3d p(s.values[0][k], s.values[1][k], s.values[2][k]);
    if (!p.allFinite()) throw InputError(file, place, "not a finite number in " + joined(names));
    if (p.cwiseAbs().maxCoeff() > kMaxFlightCoordinateM)
      throw InputError(file, place,
                       joined(names) + " further than 1e6 m from the origin: not a flight");
    if (!path.t.empty() && s.t[k] == path.t.back()) continue;
    path.t.push_back(s.t[k]);
    path.p.push_back(p);
  }
  return path;
}

bool everZero(const SampledPath& path) {
  for (const auto& p : path.p)
    if (p != Eigen::Vector3d::Zero()) return false;
  return true;
}

// The reference resampled at the position's times (a reference from another event type has
// times of its own); position samples outside the reference's time span are dropped.
void attachReference(FlightLog& log, const SampledPath& reference) {
  SampledPath position, ref;
  for (std::size_t k = 0; k < log.position.size(); ++k) {
    const double t = log.position.t[k];
    if (t < reference.start() || t > reference.end()) continue;
    position.t.push_back(t);
    position.p.push_back(log.position.p[k]);
    ref.t.push_back(t);
    ref.p.push_back(reference.at(t));
  }
  log.position = std::move(position);
  log.reference = std::move(ref);
}

}  // namespace

FlightLog parseFlightLogUsd(std::string bytes, const std::string& file,
                            const FlightLogOptions& options) {
  const UsdLog usd = UsdLog::parse(std::move(bytes), file);
  FlightLog log;
  log.file = file;
  log.format = "Crazyflie uSD log version " + std::to_string(usd.version());
  std::vector<std::string> names = options.position_vars;
  int type = -1;
  if (!names.empty()) {
    type = usd.typeWithVariables(names);
  } else {
    // The motion-capture position unless the log has it only as zeros (never sent), then the
    // estimator's.
    type = usd.typeWithVariables(kMocapPosition);
    names = kMocapPosition;
    if (type < 0 || everZero(readPath(usd, type, names, file))) {
      const int estimate = usd.typeWithVariables(kEstimatePosition);
      if (estimate >= 0) {
        type = estimate;
        names = kEstimatePosition;
      }
    }
  }
  if (type < 0)
    throw InputError(file, "header",
                     "no position variables " +
                         (options.position_vars.empty()
                              ? joined(kMocapPosition) + " or " + joined(kEstimatePosition)
                              : joined(options.position_vars)) +
                         " in one event; the log holds " + contents(usd));
  log.position = readPath(usd, type, names, file);
  log.position_source = joined(names) + " (event " + usd.eventTypes()[type].name + ")";
  const std::vector<std::string> ref_names =
      options.reference_vars.empty() ? kSetpoint : options.reference_vars;
  const int ref_type = usd.typeWithVariables(ref_names);
  if (ref_type < 0 && !options.reference_vars.empty())
    throw InputError(file, "header",
                     "no reference variables " + joined(ref_names) +
                         " in one event; the log holds " + contents(usd));
  if (ref_type >= 0) {
    const SampledPath reference = readPath(usd, ref_type, ref_names, file);
    if (reference.size() >= 2) {
      attachReference(log, reference);
      log.reference_source = joined(ref_names) + " (event " + usd.eventTypes()[ref_type].name + ")";
    }
  }
  if (log.position.size() < kMinFlightLogSamples)
    throw InputError(file, "records",
                     "too few samples: " + std::to_string(log.position.size()) + " of " +
                         joined(names) + ", at least " + std::to_string(kMinFlightLogSamples) +
                         " needed");
  return log;
}

}  // namespace cosim
