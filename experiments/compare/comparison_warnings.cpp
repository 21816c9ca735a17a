#include "experiments/compare/comparison_warnings.h"

#include <cmath>
#include <cstdio>

namespace cosim {

std::vector<std::string> comparisonWarnings(const FlightComparison& c) {
  std::vector<std::string> out;
  char buf[512];
  if (c.time_offset_fitted && std::abs(c.time_offset_s) > kLargeTimeShiftS) {
    std::snprintf(buf, sizeof buf,
                  "fitted time shift %.4f s (log time minus run time) is above %.2f s: if the "
                  "log's clock is the run's, a lag of the real flight was taken out of its error "
                  "(--align none keeps it)",
                  c.time_offset_s, kLargeTimeShiftS);
    out.emplace_back(buf);
  }
  static const char* kAxis[3] = {"x", "y", "z"};
  std::string fitted, kept;
  for (int a = 0; a < 3; ++a) {
    if (std::abs(c.mean_offset_m[a]) <= kLargeOffsetM) continue;
    std::snprintf(buf, sizeof buf, "%s %.4f m", kAxis[a], c.mean_offset_m[a]);
    std::string& list = fitsAxis(c.alignment, a) ? fitted : kept;
    list += (list.empty() ? "" : ", ") + std::string(buf);
  }
  const auto offsetWarning = [&](const std::string& axes, const char* what) {
    std::snprintf(buf, sizeof buf,
                  "mean offset of the real flight from the simulated one (%s) is above %.2f m: "
                  "%s",
                  axes.c_str(), kLargeOffsetM, what);
    out.emplace_back(buf);
  };
  if (!fitted.empty())
    offsetWarning(fitted, "fitted away by the alignment, so it is not in the real error");
  if (!kept.empty())
    offsetWarning(kept, c.real_against_log_reference
                            ? "not fitted, and not in the real error either (that is measured "
                              "against the log's own reference)"
                            : "it is in the real error (--align time+xy or time+xyz would fit it "
                              "away)");
  return out;
}

}  // namespace cosim
