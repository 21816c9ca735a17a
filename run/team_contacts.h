#pragma once
// A run's contacts by kind and its vehicles' closest approaches, from the log: each touching pair
// of vehicles counted once (both book it, sim/contact_monitor.h), contacts with static and with
// moving obstacles, and the smallest surface-to-surface distances between ground robots'
// footprints and between a robot and a moving obstacle (quadrotors fly over them).
#include <limits>
#include <vector>

#include "sim/run_log.h"
#include "sim/vehicle_kind.h"

namespace cosim {

struct TeamContacts {
  int robot_contacts = 0, obstacle_contacts = 0, moving_obstacle_contacts = 0;
  int robot_uav_contacts = 0, uav_contacts = 0;  // a quadrotor with a robot, with a quadrotor
  double min_robot_distance_m = std::numeric_limits<double>::infinity();
  double min_moving_obstacle_distance_m = std::numeric_limits<double>::infinity();

  // Every contact of the run (metrics.json's "collisions").
  int total() const {
    return robot_contacts + obstacle_contacts + moving_obstacle_contacts + robot_uav_contacts +
           uav_contacts;
  }
};

// `kinds[v]`: what log.vehicles[v] is. Vehicles and obstacles must be logged at the same instants.
TeamContacts teamContacts(const RunLog& log, const std::vector<VehicleKind>& kinds);

}  // namespace cosim
