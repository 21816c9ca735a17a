#include "planning/mapf/lacam_planner.h"

#include "planning/mapf/graph_instance.h"
#include "planning/mapf/mapf_search_context.h"

namespace cosim {

MapfResult LacamPlanner::solve(const MapfQuery& query, const StopToken& stop) {
  const MapfSearchContext context(query, stop);
  const StopToken& deadline = context.deadline();
  const GraphInstance g = graphInstance(context.instance());
  const int n = context.agentCount();
  const LacamOutcome out =
      searchLacam(g.graph, g.starts, g.goals, options_, deadline, context.seed());
  MapfResult result;
  result.success = out.status == LacamOutcome::Status::kSolved;
  result.message = out.message;
  switch (out.status) {
    case LacamOutcome::Status::kSolved:
      result.status = searchStatus(true, deadline, PlannerStatus::NoSolution);
      break;
    case LacamOutcome::Status::kNoSolution:
    case LacamOutcome::Status::kUnreachable:
      result.status = PlannerStatus::NoSolution;
      break;
    case LacamOutcome::Status::kTimeLimit:
      result.status = expiredStatus(deadline);
      break;
    case LacamOutcome::Status::kMemoryLimit:
      result.status = PlannerStatus::LimitReached;
      break;
  }
  if (result.success) {
    result.paths = pathsOfConfigurations(g.graph, out.configurations, n);
    // The first solution's sum of costs (arrival times), for the anytime report.
    result.counters["first_sum_of_costs"] = static_cast<double>(out.first_sum_of_costs);
  }
  auto& c = result.counters;
  c["first_solution_ms"] = out.first_solution_ms;
  c["first_sum_of_loss"] = static_cast<double>(out.first_sum_of_loss);
  c["final_sum_of_loss"] = static_cast<double>(out.final_sum_of_loss);
  c["improvements"] = static_cast<double>(out.improvements);
  c["last_improvement_ms"] = out.last_improvement_ms;
  c["proven_optimal"] = out.proven_optimal ? 1.0 : 0.0;
  // 1 when the time limit (or a stop request) or the memory cap cut the anytime phase short:
  // the final cost then depends on how far the search got.
  c["anytime_cut_by_time"] = out.anytime_end == LacamOutcome::AnytimeEnd::kTimeLimit ? 1.0 : 0.0;
  c["anytime_cut_by_memory"] =
      out.anytime_end == LacamOutcome::AnytimeEnd::kMemoryLimit ? 1.0 : 0.0;
  c["iterations"] = static_cast<double>(out.iterations);
  c["nodes"] = static_cast<double>(out.nodes);
  c["restarts"] = static_cast<double>(out.restarts);
  c["generator_failures"] = static_cast<double>(out.generator_failures);
  c["rediscoveries"] = static_cast<double>(out.rediscoveries);
  c["search_memory_mb"] = static_cast<double>(out.memory_bytes) / (1 << 20);
  c["distance_table_mb"] = static_cast<double>(out.distance_table_bytes) / (1 << 20);
  return context.finish(std::move(result));
}

}  // namespace cosim
