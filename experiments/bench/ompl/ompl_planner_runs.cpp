#include "experiments/bench/ompl/ompl_planner_runs.h"

#include <ompl/base/PlannerData.h>
#include <ompl/base/ProblemDefinition.h>
#include <ompl/base/ScopedState.h>
#include <ompl/base/objectives/PathLengthOptimizationObjective.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/config.h>
#include <ompl/geometric/PathGeometric.h>
#include <ompl/geometric/planners/prm/PRM.h>
#include <ompl/geometric/planners/rrt/InformedRRTstar.h>
#include <ompl/geometric/planners/rrt/RRT.h>
#include <ompl/geometric/planners/rrt/RRTConnect.h>
#include <ompl/geometric/planners/rrt/RRTstar.h>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>

#include <algorithm>
#include <chrono>

#include "experiments/bench/ompl/exact_motion_checks.h"

namespace cosim::omplbench {

namespace ob = ompl::base;
namespace og = ompl::geometric;

namespace {

// Anytime planners improve their path until the time limit (a cost threshold of 0 is never
// met), as in OMPL's own benchmarks; the others stop at their first solution, as ours do.
bool isAnytime(const std::string& name) {
  return name == "ompl_rrt_star" || name == "ompl_informed_rrt_star";
}

// A tree planner of the RRT family with its maximum edge length.
template <class TreePlanner>
ob::PlannerPtr treePlanner(const ob::SpaceInformationPtr& si, double range) {
  auto p = std::make_shared<TreePlanner>(si);
  p->setRange(range);
  return p;
}

ob::PlannerPtr makeOmplPlanner(const std::string& name, const ob::SpaceInformationPtr& si,
                               double range) {
  if (name == "ompl_rrt") return treePlanner<og::RRT>(si, range);
  if (name == "ompl_rrt_connect") return treePlanner<og::RRTConnect>(si, range);
  if (name == "ompl_rrt_star") return treePlanner<og::RRTstar>(si, range);
  if (name == "ompl_informed_rrt_star") return treePlanner<og::InformedRRTstar>(si, range);
  return std::make_shared<og::PRM>(si);  // connects its k = 10 nearest, as our prm
}

// The real vector space of the problem: the region our sampler draws from (the bounds less the
// clearance above the floor), in x, y only for planar problems.
std::shared_ptr<ob::RealVectorStateSpace> stateSpace(const CollisionWorld& world, bool planar) {
  const unsigned dim = planar ? 2 : 3;
  auto space = std::make_shared<ob::RealVectorStateSpace>(dim);
  ob::RealVectorBounds bounds(dim);
  for (unsigned i = 0; i < dim; ++i) {
    bounds.setLow(i, world.validMin()[i]);
    bounds.setHigh(i, world.validMax()[i]);
  }
  space->setBounds(bounds);
  return space;
}

// OMPL logs through its own console; a benchmark run is reported by plan-bench instead.
class QuietOmpl {
 public:
  QuietOmpl() : level_(ompl::msg::getLogLevel()) { ompl::msg::setLogLevel(ompl::msg::LOG_NONE); }
  ~QuietOmpl() { ompl::msg::setLogLevel(level_); }

 private:
  ompl::msg::LogLevel level_;
};

}  // namespace

const std::vector<std::string>& omplPlannerNames() {
  static const std::vector<std::string> names = {"ompl_rrt", "ompl_rrt_connect", "ompl_rrt_star",
                                                 "ompl_informed_rrt_star", "ompl_prm"};
  return names;
}

bool isOmplPlanner(const std::string& name) {
  const auto& names = omplPlannerNames();
  return std::find(names.begin(), names.end(), name) != names.end();
}

std::vector<std::string> omplStatusNames() {
  std::vector<std::string> names;
  for (int i = 0; i < ob::PlannerStatus::TYPE_COUNT; ++i)
    names.push_back(ob::PlannerStatus(static_cast<ob::PlannerStatus::StatusType>(i)).asString());
  return names;
}

std::string omplVersion() {
  return std::to_string(OMPL_MAJOR_VERSION) + "." + std::to_string(OMPL_MINOR_VERSION) + "." +
         std::to_string(OMPL_PATCH_VERSION);
}

int omplStatusExact() {
  return ob::PlannerStatus::EXACT_SOLUTION;
}
int omplStatusTimeout() {
  return ob::PlannerStatus::TIMEOUT;
}
int omplStatusApproximate() {
  return ob::PlannerStatus::APPROXIMATE_SOLUTION;
}

OmplPlanResult planWithOmpl(const OmplPlanRequest& request) {
  const QuietOmpl quiet;
  // Every generator OMPL creates from here on (samplers, the planner's own) draws its seed from
  // this one: the run is repeatable for its seed. (OMPL logs that the seed changed after
  // generation started; that warning is about the generators already made, not these.)
  ompl::RNG::setSeed(request.seed);
  const CollisionWorld& world = *request.world;
  const double plane_z = request.start.z();
  auto space = stateSpace(world, request.planar);
  auto si = std::make_shared<ob::SpaceInformation>(space);
  si->setStateValidityChecker(std::make_shared<ExactValidityChecker>(si, world, plane_z));
  si->setMotionValidator(std::make_shared<ExactMotionValidator>(si, world, plane_z));
  si->setup();
  ob::ScopedState<> start(space), goal(space);
  for (unsigned i = 0; i < space->getDimension(); ++i)
    start[i] = request.start[i], goal[i] = request.goal[i];
  auto pdef = std::make_shared<ob::ProblemDefinition>(si);
  pdef->setStartAndGoalStates(start, goal);
  if (isAnytime(request.planner)) {
    auto objective = std::make_shared<ob::PathLengthOptimizationObjective>(si);
    objective->setCostThreshold(ob::Cost(0.0));
    pdef->setOptimizationObjective(objective);
  }
  ob::PlannerPtr planner = makeOmplPlanner(request.planner, si, request.range);
  planner->setProblemDefinition(pdef);
  planner->setup();

  OmplPlanResult result;
  planner->params().getParams(result.params);
  const auto t0 = std::chrono::steady_clock::now();
  const ob::PlannerStatus status =
      planner->solve(ob::timedPlannerTerminationCondition(request.time_limit_s));
  result.time_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  result.status = static_cast<int>(ob::PlannerStatus::StatusType(status));
  result.exact = status == ob::PlannerStatus::EXACT_SOLUTION && pdef->hasExactSolution();
  if (result.exact) {
    auto* path = pdef->getSolutionPath()->as<og::PathGeometric>();
    for (const ob::State* s : path->getStates())
      result.path.push_back(toPoint(s, space->getDimension(), plane_z));
  }
  ob::PlannerData data(si);
  planner->getPlannerData(data);
  result.graph_states = static_cast<double>(data.numVertices());
  return result;
}

}  // namespace cosim::omplbench
