#include "experiments/compare/compare_report.h"

#include <cstdio>
#include <sstream>

#include "core/atomic_file.h"
#include "core/json_writer.h"
#include "experiments/compare/compare_figure.h"

namespace cosim {

namespace {

std::string vectorJson(const Eigen::Vector3d& v) {
  // Appended piece by piece: GCC 12's -Wrestrict misfires on operator+ chains.
  std::string s = "[";
  s += JsonObject::number(v.x());
  s += ", ";
  s += JsonObject::number(v.y());
  s += ", ";
  s += JsonObject::number(v.z());
  s += "]";
  return s;
}

double ratio(const FlightComparison& c) {
  return c.real_rmse_m / c.sim_rmse_m;
}

std::string fixed(double v, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", digits, v);
  return buf;
}

std::string significant(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

}  // namespace

std::string compareJson(const CompareInputs& in, const FlightComparison& c) {
  JsonObject j;
  j.add("real_rmse_m", c.real_rmse_m)
      .add("sim_rmse_m", c.sim_rmse_m)
      .add("ratio", ratio(c))
      .add("time_offset_s", c.time_offset_s)
      .raw("start_offset_m", vectorJson(c.start_offset_m))
      .add("real_max_error_m", c.real_max_error_m)
      .add("sim_max_error_m", c.sim_max_error_m)
      .add("samples", c.t.size())
      .add("log_samples", c.log_samples)
      .add("window_start_s", c.windowStart())
      .add("window_end_s", c.windowEnd())
      .add("time_offset_fitted", c.time_offset_fitted)
      .add("start_offset_fitted", c.start_offset_fitted)
      .add("alignment", c.alignment)
      .add("alignment_rms_m", c.alignment_rms_m)
      .add("vehicle", in.run->vehicle)
      .add("relative_reference", in.run->relative_reference)
      .add("run_dir", in.run_dir.string())
      .add("log", in.log->file)
      .add("log_format", in.log->format)
      .add("log_position", in.log->position_source)
      .add("log_reference", in.log->reference_source);
  return j.str() + "\n";
}

std::string compareMarkdown(const CompareInputs& in, const FlightComparison& c) {
  std::ostringstream s;
  s << "# Real flight beside simulation\n\n"
    << "Run `" << in.run_dir.string() << "` (vehicle " << in.run->vehicle << ") and log `"
    << in.log->file << "` (" << in.log->format << ", position from " << in.log->position_source
    << (in.log->hasReference() ? ", reference from " + in.log->reference_source : "") << ").\n\n"
    << "Window: the run's reference, " << fixed(c.windowStart(), 3) << " to "
    << fixed(c.windowEnd(), 3) << " s of run time (" << c.t.size() << " run samples, "
    << c.log_samples << " log samples).\n\n"
    << "| flight | RMSE (m) | max error (m) |\n|---|---|---|\n"
    << "| real | " << fixed(c.real_rmse_m, 4) << " | " << fixed(c.real_max_error_m, 4) << " |\n"
    << "| simulated | " << fixed(c.sim_rmse_m, 4) << " | " << fixed(c.sim_max_error_m, 4)
    << " |\n\n"
    << "Ratio real / simulated RMSE: **" << fixed(ratio(c), 3) << "**.\n\n"
    << "Placing the log: time offset (log time minus run time) " << fixed(c.time_offset_s, 4)
    << " s, " << (c.time_offset_fitted ? "fitted" : "given") << "; start offset ["
    << fixed(c.start_offset_m.x(), 4) << ", " << fixed(c.start_offset_m.y(), 4) << ", "
    << fixed(c.start_offset_m.z(), 4) << "] m, "
    << (c.start_offset_fitted
            ? std::string(in.run->relative_reference ? "fitted (the run's reference is relative "
                                                       "to the vehicle's start)"
                                                     : "fitted")
            : std::string(in.run->relative_reference
                              ? "not fitted (as asked)"
                              : "not fitted (the run's reference is absolute)"))
    << ". Least squares of " << c.alignment << "; residual RMS " << significant(c.alignment_rms_m)
    << " m.\n\n"
    << "Figure: `compare.png` (`compare.svg`): both flown paths over the reference from above, "
       "and the error over time, real beside simulated.\n";
  return s.str();
}

std::vector<std::string> writeCompareReport(const std::filesystem::path& dir,
                                            const CompareInputs& in, const FlightComparison& c) {
  writeCompareFigure(c, dir / "compare");
  writeFileAtomically(dir / "compare.md", compareMarkdown(in, c));
  // Last, so that a compare.json says the rest is there.
  writeFileAtomically(dir / "compare.json", compareJson(in, c));
  return {"compare.json", "compare.md", "compare.png", "compare.svg"};
}

}  // namespace cosim
