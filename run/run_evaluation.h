#pragma once
// The evaluation stage of a run, from its log alone (and the plan's timing): every vehicle's
// flight metrics (sim/flight_metrics.h), the team's pooled figures (run/pooled_metrics.h), its
// contacts (run/team_contacts.h), the quadrotors' separation (sim/uav_separation_metrics.h), the
// robots' arrivals against their timed plans, and the run's outcome: status and message.
#include <optional>
#include <string>
#include <vector>

#include "run/run_end.h"
#include "run/run_plan.h"
#include "run/team_contacts.h"
#include "sim/flight_metrics.h"
#include "sim/run_log.h"
#include "sim/uav_separation_metrics.h"

namespace cosim {

// The robots' arrivals against their timed plans (runs with ground robots).
struct RobotSchedule {
  std::vector<double> planned_arrival_s;  // per robot: its timed plan's end, -1 if not planned
  double planned_makespan_s = 0.0;
  double executed_makespan_s = 0.0;     // latest arrival (robots that arrived)
  double sum_of_arrival_times_s = 0.0;  // robots that arrived
};

struct RunMetrics {
  std::vector<FlightMetrics> vehicles;  // one per vehicle, in the scenario's order
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
  int status = 0;       // the exit status: 0 ok, 1 task failed
  std::string message;  // why the task failed
  double sim_speed_x = 0.0;
};

RunMetrics evaluateRun(const Scenario& scenario, const RunSetup& setup, const WorldModel& world,
                       const RunPlan& plan, const RunLog& log);

}  // namespace cosim
