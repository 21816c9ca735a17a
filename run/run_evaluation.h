#pragma once
// The evaluation stage of a run, from its log alone (and the plan's timing): every vehicle's
// flight metrics (sim/flight_metrics.h), the team's pooled figures (run/pooled_metrics.h), its
// contacts (run/team_contacts.h), the quadrotors' separation (sim/uav_separation_metrics.h), the
// robots' arrivals against their timed plans, and the run's outcome and message.
#include <memory>

#include "run/record/run_record.h"
#include "run/run_plan.h"

namespace cosim {

// The evaluate stage: the run's record, with `log` in it (the setup, the plans and the planner's
// figures, every metric, the outcome and its message). The only place a run's metrics are
// computed.
RunRecord evaluateRun(const Scenario& scenario, const RunSetup& setup,
                      const std::shared_ptr<const WorldModel>& world, const RunPlan& plan,
                      RunLog log);

// Each vehicle's flight metrics and per-sample tracking errors against its error reference
// (setup.vehicles), into `metrics`.
void evaluateVehicles(const Scenario& scenario, const RunSetup& setup, const RunLog& log,
                      RunMetrics& metrics);

// The flight metrics of a reference flight's vehicle (run/given_reference_flight.h): it flies a
// reference in time, so its error is measured against that trajectory.
FlightMetrics evaluateReferenceFlight(const Scenario& scenario, const RunLog& log);

// Each vehicle's per-sample tracking errors against its error reference, into `metrics`: they
// depend on the logged samples alone.
void trackVehicles(const RunSetup& setup, const RunLog& log, RunMetrics& metrics);

// The record of a log the pipeline did not fly (a benchmark's or a test's hand-made flight):
// the setup resolved from `scenario` as a run resolves it, `log`, and each vehicle's flight
// metrics and tracking errors (evaluateVehicles). No plans, no pooled figures, outcome Succeeded.
// `world` is shared; the reference form does not own it (it must outlive the record).
RunRecord recordOfLog(const Scenario& scenario, RunLog log,
                      std::shared_ptr<const WorldModel> world);
RunRecord recordOfLog(const Scenario& scenario, RunLog log, const WorldModel& world);

}  // namespace cosim
