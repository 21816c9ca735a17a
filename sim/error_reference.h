#pragma once
// What a vehicle's tracking error is measured against. It lives beside the flight metrics
// (sim/flight_metrics.h), which are measured against it; a run resolves each vehicle's once
// (run/record/run_setup.h) and everything downstream reads it from the run's record.
namespace cosim {

// A ground robot is measured against its timed plan (the plan-vs-executed deviation), a
// quadrotor against its reference trajectory when it flies a time-parametrised one (a
// trajectory mode, or a given reference), else against its planned path (a waypoint reference
// jumps between waypoints, so the distance to it says nothing). Pooled figures of several
// vehicles (run/pooled_metrics.h) have their members' common reference, Mixed when they differ,
// and None when the pool is empty.
enum class ErrorReference { TimedPlan, Trajectory, PlannedPath, Mixed, None };

// metrics.json's word: "timed_plan", "trajectory", "path", "mixed", "".
const char* errorReferenceKey(ErrorReference r);
// For a person: "timed plan", "reference trajectory", "planned path", "each vehicle's own
// reference", ""; short: "plan", "reference", "path", "own reference", "".
const char* errorReferenceName(ErrorReference r);
const char* errorReferenceShortName(ErrorReference r);

}  // namespace cosim
