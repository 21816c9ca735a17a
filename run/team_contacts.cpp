#include "run/team_contacts.h"

#include <algorithm>

namespace cosim {

namespace {

void countContacts(const RunLog& log, const std::vector<VehicleKind>& kinds, TeamContacts& t) {
  for (std::size_t v = 0; v < log.vehicles.size(); ++v) {
    for (const ContactEvent& c : log.vehicles[v].collisions) {
      bool vehicle = false;
      for (std::size_t w = 0; w < log.vehicles.size(); ++w) {
        if (w == v || c.other.rfind(log.vehicles[w].name + "/", 0) != 0) continue;
        vehicle = true;
        if (w < v) continue;  // each touching pair is booked by both vehicles
        int& count = kinds[v] != kinds[w]                   ? t.robot_uav_contacts
                     : kinds[v] == VehicleKind::GroundRobot ? t.robot_contacts
                                                            : t.uav_contacts;
        ++count;
      }
      if (vehicle) continue;
      if (c.other.rfind("moving", 0) == 0)
        ++t.moving_obstacle_contacts;
      else
        ++t.obstacle_contacts;
    }
  }
}

void closestApproaches(const RunLog& log, const std::vector<VehicleKind>& kinds, TeamContacts& t) {
  for (std::size_t v = 0; v < log.vehicles.size(); ++v) {
    if (kinds[v] != VehicleKind::GroundRobot) continue;
    const auto& a = log.vehicles[v];
    for (std::size_t k = 0; k < a.samples.size(); ++k) {
      for (std::size_t w = v + 1; w < log.vehicles.size(); ++w) {
        const auto& b = log.vehicles[w];
        if (kinds[w] == VehicleKind::GroundRobot && k < b.samples.size())
          t.min_robot_distance_m = std::min(
              t.min_robot_distance_m,
              (a.samples[k].pos - b.samples[k].pos).head<2>().norm() - a.radius - b.radius);
      }
      for (const auto& o : log.moving_obstacles)
        if (k < o.pos.size())
          t.min_moving_obstacle_distance_m =
              std::min(t.min_moving_obstacle_distance_m,
                       (a.samples[k].pos - o.pos[k]).head<2>().norm() - a.radius - o.radius);
    }
  }
}

}  // namespace

TeamContacts teamContacts(const RunLog& log, const std::vector<VehicleKind>& kinds) {
  TeamContacts t;
  countContacts(log, kinds, t);
  closestApproaches(log, kinds, t);
  return t;
}

}  // namespace cosim
