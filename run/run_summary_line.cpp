#include "run/run_summary_line.h"

#include <cmath>
#include <sstream>

namespace cosim {

namespace {

// A number as the console has always printed it (6 significant digits); "none" where
// metrics.json has null (not finite: no obstacles to measure a clearance to).
std::string number(double v) {
  if (!std::isfinite(v)) return "none";
  std::ostringstream s;
  s << v;
  return s.str();
}

// "min clearance 0.256 m"; "none (no obstacles)" where there is nothing to measure to; a negative
// clearance says what it means (min_clearance_m is measured from the vehicle's bounding sphere,
// collisions count contacts of its real geometry, which lies inside the sphere: docs/metrics.md).
std::string clearanceText(double clearance, int collisions) {
  if (!std::isfinite(clearance)) return "min clearance none (no obstacles)";
  std::string text = "min clearance " + number(clearance) + " m";
  if (clearance < 0.0)
    text += collisions == 0 ? " (bounding sphere into an obstacle, no part touched it)"
                            : " (bounding sphere into an obstacle)";
  return text;
}

}  // namespace

std::string errorReferenceWords(ErrorReference reference) {
  switch (reference) {
    case ErrorReference::Trajectory:
      return "the reference trajectory";
    case ErrorReference::PlannedPath:
      return "the planned path";
    case ErrorReference::TimedPlan:
      return "the timed plan";
    case ErrorReference::Mixed:
      return "each vehicle's reference";
    case ErrorReference::None:
      break;
  }
  return "";
}

std::string runSummaryLine(const RunRecord& r) {
  const RunMetrics& m = r.metrics;
  const FlightMetrics& team = m.team;
  // Robots with quadrotors over them: the top level is the robots'; the quadrotors' follow.
  const bool mixed =
      r.setup.primaryKind() == VehicleKind::GroundRobot && !r.setup.quadrotors.empty();
  std::ostringstream s;
  if (mixed)
    s << "robots (" << r.setup.robots.size() << ", pooled): ";
  else if (r.log.vehicles.size() > 1)
    s << "team of " << r.log.vehicles.size() << " (pooled): ";
  s << "reached_goal " << (m.reached_goal ? "yes" : "no") << ", collisions " << number(m.collisions)
    << ", flight " << number(team.flight_time_s) << " s, rmse " << number(team.rmse_m)
    << " m (against " << errorReferenceWords(team.error_reference) << "), max error "
    << number(team.max_error_m) << " m, " << clearanceText(m.min_clearance_m, m.collisions);
  if (mixed)
    s << "; quadrotors (" << r.setup.quadrotors.size() << ", pooled): rmse "
      << number(m.uavs.rmse_m) << " m, max error " << number(m.uavs.max_error_m) << " m";
  s << ", " << number(m.sim_speed_x) << "x real time";
  return s.str();
}

std::string runPagesLine(const std::filesystem::path& dir) {
  if (!std::filesystem::exists(dir / "index.html")) return "results in " + dir.string();
  std::string line = "open " + (dir / "index.html").string();
  if (std::filesystem::exists(dir / "viewer.html")) line += " or " + (dir / "viewer.html").string();
  return line;
}

}  // namespace cosim
