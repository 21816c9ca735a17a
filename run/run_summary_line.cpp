#include "run/run_summary_line.h"

#include <sstream>

namespace cosim {

namespace {

// A number as the console has always printed it (6 significant digits); "none" where
// metrics.json has null (no obstacles to measure a clearance to), "?" if absent.
std::string number(const nlohmann::ordered_json& j, const char* key) {
  const auto it = j.find(key);
  if (it != j.end() && it->is_null()) return "none";
  if (it == j.end() || !it->is_number()) return "?";
  std::ostringstream s;
  s << it->get<double>();
  return s.str();
}

}  // namespace

std::string errorReferenceWords(const std::string& reference) {
  if (reference == "trajectory") return "the reference trajectory";
  if (reference == "path") return "the planned path";
  if (reference == "timed_plan") return "the timed plan";
  if (reference == "mixed") return "each vehicle's reference";
  return reference;
}

std::string runSummaryLine(const nlohmann::ordered_json& m) {
  std::ostringstream s;
  const auto vehicles = m.find("vehicles");
  const auto robots = m.find("robots"), uavs = m.find("uavs");
  const bool mixed = uavs != m.end() && robots != m.end() && robots->is_number();
  if (mixed)  // the top level is the robots'; the quadrotors' figures follow
    s << "robots (" << robots->get<int>() << ", pooled): ";
  else if (vehicles != m.end() && vehicles->is_array() && vehicles->size() > 1)
    s << "team of " << vehicles->size() << " (pooled): ";
  const auto reached = m.find("reached_goal");
  const auto reference = m.find("error_reference");
  s << "reached_goal "
    << (reached != m.end() && reached->is_boolean() && reached->get<bool>() ? "yes" : "no")
    << ", collisions " << number(m, "collisions") << ", flight " << number(m, "flight_time_s")
    << " s, rmse " << number(m, "rmse_m") << " m (against "
    << errorReferenceWords(reference != m.end() && reference->is_string()
                               ? reference->get<std::string>()
                               : std::string("?"))
    << "), max error " << number(m, "max_error_m") << " m, min clearance "
    << number(m, "min_clearance_m") << " m";
  if (mixed)
    s << "; quadrotors (" << number(m, "uavs") << ", pooled): rmse " << number(m, "uav_rmse_m")
      << " m, max error " << number(m, "uav_max_error_m") << " m";
  s << ", " << number(m, "sim_speed_x") << "x real time";
  return s.str();
}

std::string runPagesLine(const std::filesystem::path& dir) {
  if (!std::filesystem::exists(dir / "index.html")) return "results in " + dir.string();
  std::string line = "open " + (dir / "index.html").string();
  if (std::filesystem::exists(dir / "viewer.html")) line += " or " + (dir / "viewer.html").string();
  return line;
}

}  // namespace cosim
