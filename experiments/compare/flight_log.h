#pragma once
// A real flight's log as one table, whatever file it came from: times, positions and, when the
// log has them, the reference positions the vehicle was commanded to. Two formats, told apart by
// their content (the uSD log's first byte is 0xBC; anything else is read as text):
//   a CSV with header t,x,y,z and optionally ref_x,ref_y,ref_z (seconds, metres; other columns
//   are ignored), one sample per row;
//   a Crazyflie uSD-card binary log (experiments/compare/usd_log_reader.h), whose position
//   variables are picked by name (FlightLogOptions).
// Bad input is an InputError naming the file and the line or byte: a bad header, a value that is
// not a finite number, a coordinate beyond kMaxFlightCoordinateM, times that do not increase, fewer
// than kMinFlightLogSamples samples.
#include <string>
#include <vector>

#include "experiments/compare/sampled_path.h"

namespace cosim {

// Fewer samples than this cannot place a flight in time.
constexpr std::size_t kMinFlightLogSamples = 10;

struct FlightLogOptions {
  // uSD logs: three variable names for the position (empty: locSrv.x/y/z, the motion-capture
  // position sent to the vehicle, unless the log never set it; else stateEstimate.x/y/z) and
  // for the reference (empty: ctrltarget.x/y/z when the log has them).
  std::vector<std::string> position_vars, reference_vars;
};

struct FlightLog {
  std::string file;
  std::string format;            // "csv" or "Crazyflie uSD log version N"
  std::string position_source;   // the columns or variables read, e.g. "locSrv.x,locSrv.y,locSrv.z"
  std::string reference_source;  // empty when the log has no reference
  SampledPath position;
  SampledPath reference;  // at the position's times; empty when the log has none
  bool hasReference() const { return !reference.t.empty(); }
};

// Reads `path` (a regular file, at most kMaxLogFileBytes) in whichever format it is.
FlightLog readFlightLog(const std::string& path, const FlightLogOptions& options = {});

// The two readers on a file's bytes (`file` names it in errors).
FlightLog parseFlightLogCsv(const std::string& text, const std::string& file);
FlightLog parseFlightLogUsd(std::string bytes, const std::string& file,
                            const FlightLogOptions& options = {});

}  // namespace cosim
