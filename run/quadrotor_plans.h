#pragma once
// The quadrotors' plans for a run: each quadrotor's path (jointly by a team planner,
// run/quadrotor_team_planning.h, or each alone, run/scenario_planning.h: the scenario's planner
// or its given waypoints) and the reference that path becomes (seed 003's waypoint switching, a
// minimum-snap trajectory within the airframe's limits, or the team's timed trajectory).
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "control/quadrotor_params.h"
#include "control/reference_source.h"
#include "run/group_plan.h"
#include "run/quadrotor_team_planning.h"
#include "run/record/run_setup.h"
#include "run/run_events.h"
#include "run/scenario_planning.h"
#include "sim/world_model.h"

namespace cosim {

struct RunRequest;

struct QuadrotorPlans {
  PlanStatus status = PlanStatus::Ready;
  std::string failure;             // "no path found: ..." or "no feasible trajectory: ..."
  std::vector<VehiclePlan> plans;  // one per quadrotor asked for
  // What each quadrotor's flight software believes of its airframe (sim/model_error.h): its
  // trajectory's thrust limit and its controller use it. One per quadrotor.
  std::vector<QuadrotorParams> airframes;
  // One per quadrotor when every one planned and fitted (status Ready), else empty.
  std::vector<std::unique_ptr<ReferenceSource>> references;
  PlanSummary summary;
  // Counters of the first quadrotor's minimum-snap fit (metrics.json's trajectory_counters).
  std::map<std::string, double> trajectory_counters;
};

// Plans scenario.vehicles[i] (flying world.vehicles()[i]) for each i in `vehicles` with the
// planner and trajectory of `sections` (the team's controller too: its tracking error widens the
// team's separation; `repairs`: what verification flights of its earlier plan asked for).
// Throws InputError for bad planner or trajectory parameters.
QuadrotorPlans planQuadrotors(const Scenario& scenario, const MotionSections& sections,
                              const WorldModel& world, const std::vector<std::size_t>& vehicles,
                              Planning planning, const RunRequest& request,
                              const RunReporter& report, const TeamRepairs& repairs = {});

}  // namespace cosim
