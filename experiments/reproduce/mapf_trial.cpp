#include "experiments/reproduce/mapf_trial.h"

#include <cmath>

#include "experiments/reproduce/report_files.h"
#include "planning/mapf/mapf_planner_registry.h"
#include "planning/mapf/solution_validator.h"

namespace cosim {

std::string formatFixed(double v, int digits) {
  return std::isnan(v) ? "-" : reproduce::fixed(v, digits);
}

MapfTrial runMapfTrial(const std::string& planner,
                       const std::vector<std::pair<std::string, std::string>>& params,
                       const MapfInstance& instance, double time_limit_s, std::uint64_t seed) {
  ParamSet set("reproduction");
  for (const auto& [key, value] : params) set.set(key, value);
  auto algorithm = makeMapfPlanner(planner, set);
  MapfQuery query;
  query.instance = &instance;
  query.time_limit_s = time_limit_s;
  query.seed = seed;
  const MapfResult result = algorithm->solve(query, StopToken::untimed());
  const MapfValidation check = validateMapfSolution(instance, result.paths);
  MapfTrial trial;
  trial.solved = result.success && check.valid();
  trial.time_ms = result.time_ms;
  trial.conflicts = static_cast<int>(check.conflicts.size());
  trial.paths = result.paths;
  trial.message =
      trial.solved ? "" : (result.message.empty() ? "conflicting paths" : result.message);
  if (trial.solved) {
    trial.sum_of_costs = sumOfCosts(result.paths);
    trial.makespan = makespan(result.paths);
  }
  return trial;
}

}  // namespace cosim
