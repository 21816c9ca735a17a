#pragma once
// A run's figures as its evaluation measured them (run/run_evaluation.h), typed: every vehicle's
// flight metrics and the per-sample tracking error they were taken from, the pooled figures
// metrics.json reports at its top level, the contacts, separation and schedule. Computed once,
// in the evaluation; read by everything that shows them.
#include <limits>
#include <optional>
#include <vector>

#include "sim/flight_metrics.h"
#include "sim/run_log.h"
#include "sim/uav_separation_metrics.h"

namespace cosim {

// A run's contacts by kind and its vehicles' closest approaches (run/team_contacts.h counts them).
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

// The robots' arrivals against their timed plans (runs with ground robots).
struct RobotSchedule {
  std::vector<double> planned_arrival_s;  // per robot: its timed plan's end, -1 if not planned
  double planned_makespan_s = 0.0;
  double executed_makespan_s = 0.0;     // latest arrival (robots that arrived)
  double sum_of_arrival_times_s = 0.0;  // robots that arrived
};

struct RunMetrics {
  // One per vehicle, in the scenario's order; error_reference is the vehicle's
  // (RunSetup::vehicles).
  std::vector<FlightMetrics> vehicles;
  // Per vehicle, the position error of every logged sample against its error reference
  // (sim/flight_metrics.h trackingErrors): what the pictures and figures colour by.
  std::vector<std::vector<double>> tracking_errors;
  // The top-level sections' vehicles (RunSetup::primary) pooled: metrics.json's top-level
  // tracking figures. A team is reported as a whole, a single vehicle as itself.
  FlightMetrics team;
  FlightMetrics uavs;  // the quadrotors over ground robots pooled (runs with both)
  TeamContacts contacts;
  std::optional<UavSeparationMetrics> separation;  // two or more quadrotors
  double longest_saturation_s = 0.0;               // of any quadrotor
  RobotSchedule schedule;

  // Outcome figures count every vehicle of the run.
  bool reached_goal = false;  // every vehicle reached its goal (and the plan could be driven)
  int collisions = 0;         // contacts, each touching pair once (TeamContacts::total)
  double min_clearance_m = 0.0;
  RunEnd end = RunEnd::Goal;
  double sim_speed_x = 0.0;
};

}  // namespace cosim
