#include "run/run_pipeline.h"

#include "run/prepared_run.h"
#include "run/run_simulation.h"

namespace cosim {

bool stopRequestedFor(const RunRequest& request) {
  return request.interrupt && request.interrupt->load();
}

RunRecord interruptedRun() {
  RunRecord s;
  s.outcome = RunOutcome::Interrupted;
  s.message = "interrupted";
  return s;
}

RunRecord executeRun(const Scenario& scenario, const RunRequest& request) {
  PreparedRun run = prepareRun(scenario, request);
  if (run.stopped) return interruptedRun();
  RunLog log = flyRun(run);
  if (log.end_reason == RunEnd::Interrupted) return interruptedRun();
  return concludeRun(run, std::move(log));
}

}  // namespace cosim
