#include "experiments/compare/compare_report.h"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "core/atomic_file.h"
#include "core/json_writer.h"
#include "experiments/compare/compare_figure.h"

namespace cosim {

namespace {

std::string fixed(double v, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", digits, v);
  return buf;
}

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

std::string stringsJson(const std::vector<std::string>& items) {
  std::string s = "[";
  for (std::size_t i = 0; i < items.size(); ++i) {
    if (i) s += ", ";
    s += JsonObject::quote(items[i]);
  }
  s += "]";
  return s;
}

JsonObject byAlignmentJson(const FlightComparison& c) {
  JsonObject all;
  for (const AlignmentOutcome& o : c.by_alignment) {
    JsonObject one;
    one.add("real", o.real_rmse_m)
        .add("sim", o.sim_rmse_m)
        .add("ratio", o.real_rmse_m / o.sim_rmse_m)
        .add("time_offset_s", o.time_offset_s)
        .raw("start_offset_m", vectorJson(o.translation_m));
    all.add(alignModeName(o.mode), one);
  }
  return all;
}

JsonObject realAndSim(const Eigen::Vector3d& real, const Eigen::Vector3d& sim) {
  JsonObject j;
  j.raw("real", vectorJson(real)).raw("sim", vectorJson(sim));
  return j;
}

std::string triple(const Eigen::Vector3d& v, int digits) {
  std::string s;
  for (int a = 0; a < 3; ++a) {
    if (a) s += ", ";
    s += std::isfinite(v[a]) ? fixed(v[a], digits) : std::string("-");
  }
  return s;
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
      .add("ratio", c.ratio())
      .add("alignment", alignModeName(c.alignment))
      .add("time_offset_s", c.time_offset_s)
      .raw("start_offset_m", vectorJson(c.start_offset_m))
      .raw("mean_offset_m", vectorJson(c.mean_offset_m))
      .add("rmse_by_alignment", byAlignmentJson(c))
      .add("axis_lag_s", realAndSim(c.real_axes.lag_s, c.sim_axes.lag_s))
      .add("amplitude_ratio", realAndSim(c.real_axes.amplitude_ratio, c.sim_axes.amplitude_ratio))
      .raw("warnings", stringsJson(c.warnings))
      .add("real_max_error_m", c.real_max_error_m)
      .add("sim_max_error_m", c.sim_max_error_m)
      .add("samples", c.t.size())
      .add("log_samples", c.log_samples)
      .add("window_start_s", c.windowStart())
      .add("window_end_s", c.windowEnd())
      .add("time_offset_fitted", c.time_offset_fitted)
      .add("start_offset_fitted", c.start_offset_fitted)
      .add("alignment_target", c.alignment_target)
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
    << "Ratio real / simulated RMSE: **" << fixed(c.ratio(), 3) << "** (alignment `"
    << alignModeName(c.alignment) << "`).\n\n"
    << "Placing the log: time offset (log time minus run time) " << fixed(c.time_offset_s, 4)
    << " s, " << (c.time_offset_fitted ? "fitted" : "given") << "; start offset ["
    << fixed(c.start_offset_m.x(), 4) << ", " << fixed(c.start_offset_m.y(), 4) << ", "
    << fixed(c.start_offset_m.z(), 4) << "] m, "
    << (c.start_offset_fitted ? "fitted" : "not fitted") << ". Least squares of "
    << c.alignment_target << "; residual RMS " << significant(c.alignment_rms_m)
    << " m. Mean offset of the real flight from the simulated "
    << "one after the time alignment [" << triple(c.mean_offset_m, 4) << "] m.\n\n"
    << "| alignment | time offset (s) | start offset (m) | real RMSE (m) | simulated RMSE (m) | "
       "ratio |\n|---|---|---|---|---|---|\n";
  for (const AlignmentOutcome& o : c.by_alignment)
    s << "| " << alignModeName(o.mode) << " | " << fixed(o.time_offset_s, 4) << " | "
      << triple(o.translation_m, 4) << " | " << fixed(o.real_rmse_m, 4) << " | "
      << fixed(o.sim_rmse_m, 4) << " | " << fixed(o.real_rmse_m / o.sim_rmse_m, 3) << " |\n";
  s << "\nPer axis x, y, z against the run's reference (- where the reference does not move "
       "along the axis): lag real ["
    << triple(c.real_axes.lag_s, 3) << "] s, simulated [" << triple(c.sim_axes.lag_s, 3)
    << "] s; amplitude ratio real [" << triple(c.real_axes.amplitude_ratio, 3) << "], simulated ["
    << triple(c.sim_axes.amplitude_ratio, 3) << "].\n\n";
  for (const std::string& w : c.warnings) s << "Warning: " << w << "\n\n";
  s << "Figure: `compare.png` (`compare.svg`): both flown paths over the reference from above, "
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
