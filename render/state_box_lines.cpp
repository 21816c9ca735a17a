#include "render/state_box_lines.h"

#include <cstdio>

namespace cosim {

namespace {

std::string format(const char* pattern, double value) {
  char buf[48];
  std::snprintf(buf, sizeof buf, pattern, value);
  return buf;
}

// One line per vehicle: its name, then speed and error.
StateLine vehicleLine(const StateBoxVehicle& v) {
  return {v.name, format("%.2f m/s, ", v.speed) + format("%.3f m", v.error)};
}

// Two lines for a group of vehicles of one kind ("robot", "quadrotor"): how many are at their
// goals, and the largest error with whose it is.
void summarise(const std::vector<const StateBoxVehicle*>& group, const std::string& kind,
               std::vector<StateLine>& lines) {
  std::size_t at_goal = 0;
  const StateBoxVehicle* worst = group.front();
  for (const StateBoxVehicle* v : group) {
    at_goal += v->at_goal ? 1 : 0;
    if (v->error > worst->error) worst = v;
  }
  lines.emplace_back(kind + "s at goal",
                     std::to_string(at_goal) + " / " + std::to_string(group.size()));
  lines.emplace_back("worst " + kind + " error",
                     format("%.3f m", worst->error) + " (" + worst->name + ")");
}

}  // namespace

std::vector<StateLine> stateBoxLines(double t, const std::vector<StateBoxVehicle>& vehicles,
                                     const std::vector<StateLine>& planners,
                                     std::size_t max_lines) {
  std::vector<StateLine> lines;
  lines.emplace_back("time", format("%.2f s", t));
  if (vehicles.size() == 1) {
    lines.emplace_back("speed", format("%.2f m/s", vehicles[0].speed));
    lines.emplace_back(std::string("error to ") + errorReferenceShortName(vehicles[0].reference),
                       format("%.3f m", vehicles[0].error));
  } else if (!vehicles.empty()) {
    std::vector<const StateBoxVehicle*> robots, quadrotors;
    for (const StateBoxVehicle& v : vehicles)
      (v.kind == VehicleKind::GroundRobot ? robots : quadrotors).push_back(&v);
    const std::size_t fixed = lines.size() + planners.size();
    const std::size_t budget = max_lines > fixed ? max_lines - fixed : 0;
    bool list_robots = robots.size() <= kListedRobots, list_quadrotors = true;
    const auto needed = [&] {
      const std::size_t listed =
          (list_robots ? robots.size() : 0) + (list_quadrotors ? quadrotors.size() : 0);
      const std::size_t summaries = (!list_robots && !robots.empty() ? 2 : 0) +
                                    (!list_quadrotors && !quadrotors.empty() ? 2 : 0);
      return (listed ? listed + 1 : 0) + summaries;  // + 1: the column heading
    };
    // A group of one or two is no longer as a summary (two lines): it stays listed.
    if (needed() > budget && list_robots && robots.size() > 2) list_robots = false;
    if (needed() > budget && quadrotors.size() > 2) list_quadrotors = false;
    // The column heading goes first when room is short.
    if (((list_robots && !robots.empty()) || (list_quadrotors && !quadrotors.empty())) &&
        needed() <= budget)
      lines.emplace_back("vehicle", "speed, error");
    for (const StateBoxVehicle& v : vehicles)
      if (v.kind == VehicleKind::GroundRobot ? list_robots : list_quadrotors)
        lines.push_back(vehicleLine(v));
    if (!list_robots && !robots.empty()) summarise(robots, "robot", lines);
    if (!list_quadrotors && !quadrotors.empty()) summarise(quadrotors, "quadrotor", lines);
  }
  if (lines.size() + planners.size() > max_lines && planners.size() > 1) {
    // Short of room: the planners (and controllers) on one line.
    bool only_planners = true;
    for (const StateLine& p : planners)
      only_planners = only_planners && p.first.find("planner") != std::string::npos;
    StateLine joined{only_planners ? "planners" : "set-up", ""};
    for (const StateLine& p : planners)
      joined.second += (joined.second.empty() ? "" : " / ") + p.second;
    lines.push_back(joined);
  } else {
    lines.insert(lines.end(), planners.begin(), planners.end());
  }
  return lines;
}

}  // namespace cosim
