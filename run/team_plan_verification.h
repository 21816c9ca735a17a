#pragma once
// A quadrotor team's plan flown before it is trusted: after the team is planned and smoothed, the
// prepare stage flies it in the simulation loop itself (the same world, vehicles, controllers,
// downwash and seed; no rendering, no files) and measures every pair's flown ellipsoidal distance.
// Where a pair comes closer than its separation ellipsoid (or touches), the plan is repaired where
// it broke and flown again, at most team.verify_rounds times:
// 1. the pair is made to rest at the waypoints around that instant (it flies the lock-step moves
//    there, which the roadmap keeps apart, at the speed the step time allows);
// 2. a pair that breaks again where it already rests: the whole team's separation is widened by
//    what the flight lacked (the roadmap and search again), while the starts and goals allow;
// 3. beyond that, the team is slowed (its step time stretched).
// The loop is deterministic, so the run's own flight is the last verification flight (its log is
// kept, and `cosim run` does not fly it again). A plan that still breaks after the last round
// fails the run (exit 1) with the pairs and instants that conflict, flown all the same.
#include <optional>

#include "run/record/plan_verification_report.h"
#include "sim/run_log.h"

namespace cosim {

struct PreparedRun;

// Verifies (and repairs) the team plan of `run`, a run of quadrotors alone planned as a team
// whose plan is drivable. Replaces run.plan.quadrotors and run.pilots when it repairs; sets
// run.plan.status to Conflicting with the message when the plan cannot be made clean; sets
// run.stopped when the interrupt flag stopped a flight. Returns the last flight's log.
std::optional<RunLog> verifyTeamPlan(PreparedRun& run, PlanVerificationReport& report);

// Whether `run` is one whose plan verifyTeamPlan checks.
bool verifiesTeamPlan(const PreparedRun& run);

}  // namespace cosim
