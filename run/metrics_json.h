#pragma once
// metrics.json: one definition for every kind of run (a quadrotor, a quadrotor team, ground
// robots, robots with quadrotors over them, a navigator, given waypoints).
//
// The top-level tracking figures (planned_length_m, flown_length_m, flight_time_s, rmse_m,
// max_error_m, and a flight's peak_thrust_fraction, saturated_fraction, energy_proxy,
// max_speed_mps, estimation_rmse_m) are those of the vehicles the top-level planner, trajectory
// and controller drive, pooled over all of them (run/pooled_metrics.h): a team is reported as a
// whole, the way a researcher compares teams, and a single vehicle as itself. In a run with
// ground robots those are the robots; the quadrotors over them (the `aerial` sections) have the
// uav_* figures, pooled the same way. The outcome figures (reached_goal, collisions,
// min_clearance_m) count every vehicle of the run, each touching pair of vehicles once.
#include "core/json_writer.h"
#include "run/record/run_setup.h"
#include "run/run_evaluation.h"
#include "run/run_plan.h"
#include "sim/run_log.h"
#include "sim/world_model.h"

namespace cosim {

// metrics.json's object of a run of `scenario`: the one writer of metrics.json, from the record.
JsonObject runMetricsJson(const Scenario& scenario, const RunRecord& record);

// A quadrotor's entry in metrics.json's "vehicles" list (without its name and model).
JsonObject flightMetricsJson(const FlightMetrics& m);

}  // namespace cosim
