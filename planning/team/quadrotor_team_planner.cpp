#include "planning/team/quadrotor_team_planner.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <set>
#include <tuple>

#include "core/input_error.h"
#include "planning/mapf/solution_validator.h"
#include "planning/team/dense_roadmap.h"
#include "planning/team/dense_team_search.h"
#include "planning/team/ellipsoid_conflict.h"
#include "planning/team/team_grid.h"

namespace cosim {

namespace {

// The lock-step plan's closest approach (one agent turning off the cell another is entering) is
// exactly pitch / sqrt(2): a hair more pitch keeps round-off from making that a violation.
constexpr double kPitchRoundOff = 1.0 + 1e-6;

double msSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

// The ellipsoid every pair keeps: the largest semi-axes of the team.
SeparationEllipsoid teamEllipsoid(const std::vector<TeamAgent>& agents) {
  SeparationEllipsoid e{0.0, 0.0};
  for (const auto& a : agents) e = SeparationEllipsoid::between(e, a.separation);
  return e;
}

Cell snappedCell(const TeamGrid& grid, const Eigen::Vector3d& p, const std::string& place,
                 std::set<std::tuple<int, int, int>>& taken) {
  const Cell c = grid.cellOf(p);
  if (grid.occupancy().blocked(c))
    throw InputError("", place,
                     "lies in a blocked cell of the team's grid (too close to an obstacle or the "
                     "bounds for the vehicle's radius plus planner.margin), or outside it");
  if (!taken.insert({c.x, c.y, c.z}).second)
    throw InputError("", place,
                     "shares its cell of the team's grid with another vehicle's (cells are " +
                         std::to_string(grid.pitch().x()) + " m wide, " +
                         std::to_string(grid.pitch().z()) +
                         " m high: sqrt(2) x planner.min_separation separation ellipsoids); "
                         "move them further apart");
  return c;
}

MapfInstance snappedInstance(const TeamGrid& grid, const std::vector<TeamAgent>& agents) {
  MapfInstance instance;
  instance.grid = grid.occupancy();
  instance.connectivity = instance.grid.is3D() ? 6 : 4;
  std::set<std::tuple<int, int, int>> starts, goals;
  for (std::size_t i = 0; i < agents.size(); ++i) {
    const std::string key = "vehicles[" + std::to_string(i) + "]";
    instance.starts.push_back(snappedCell(grid, agents[i].start, key + ".start", starts));
    instance.goals.push_back(snappedCell(grid, agents[i].goal, key + ".goal", goals));
  }
  return instance;
}

// start, the start cell's centre, the plan's cells (held until the makespan), goal.
std::vector<Eigen::Vector3d> stepPoints(const TeamGrid& grid, const TeamAgent& agent,
                                        const MapfPath& path, int makespan) {
  std::vector<Eigen::Vector3d> p{agent.start};
  for (int t = 0; t <= makespan; ++t)
    p.push_back(grid.centre(path[std::min<std::size_t>(t, path.size() - 1)]));
  p.push_back(agent.goal);
  return p;
}

}  // namespace

double teamStepDuration(const Eigen::Vector3d& pitch, double max_speed, double max_acceleration) {
  const double longest = pitch.maxCoeff();
  return std::max(35.0 / 16.0 * longest / max_speed, std::sqrt(7.51 * longest / max_acceleration));
}

namespace {

using Say = std::function<void(const std::string&)>;

// The MAPF stage: true when the planner's solution passes the independent validator; else the
// plan says why.
bool searchGrid(const TeamPlanningProblem& problem, MapfPlanner& planner,
                const MapfInstance& instance, const StopToken& deadline, TeamPlan& plan,
                MapfResult& r) {
  MapfQuery query;
  query.instance = &instance;
  query.time_limit_s = std::max(1e-3, problem.time_limit_s - deadline.elapsedMs() / 1000.0);
  query.seed = problem.seed;
  try {
    r = planner.solve(query, StopToken::untimed(problem.stop));
  } catch (const InputError& e) {  // e.g. a planner for 2D grids only
    throw InputError("", "planner.name", "'" + planner.name() + "': " + e.problem());
  }
  for (const auto& [k, v] : r.counters) plan.counters[k] = v;
  plan.counters["mapf_ms"] = r.time_ms;
  const MapfValidation check = validateMapfSolution(instance, r.paths);
  if (r.success && check.problems.empty() && check.conflicts.empty()) return true;
  plan.status = r.success ? PlannerStatus::InvalidSolution : r.status;
  plan.message =
      "no team plan on the grid: " + (!r.message.empty() ? r.message
                                      : !check.problems.empty()
                                          ? check.problems.front()
                                          : std::to_string(check.conflicts.size()) + " conflicts");
  return false;
}

// The continuous-time stage: the grid paths smoothed and repaired, with a progress line a
// second at most.
void smoothGrid(const TeamPlanningProblem& problem, const TeamGrid& grid, const MapfResult& r,
                const StopToken& deadline, const Say& say, TeamPlan& plan) {
  const auto smoothing_start = std::chrono::steady_clock::now();
  const int steps = makespan(r.paths);
  std::vector<TeamMember> team;
  for (std::size_t i = 0; i < problem.agents.size(); ++i) {
    const TeamAgent& a = problem.agents[i];
    plan.points.push_back(stepPoints(grid, a, r.paths[i], steps));
    team.push_back({plan.points.back(), a.separation, a.clearance, {}});
    if (i < problem.rest_steps.size()) team.back().rest_steps = problem.rest_steps[i];
  }
  TeamTrajectoryOptions options;
  options.step_duration = problem.step_stretch * teamStepDuration(grid.pitch(), problem.max_speed,
                                                                  problem.max_acceleration);
  options.min_separation = problem.min_separation;
  options.deadline = &deadline;
  say("team plan: " + std::to_string(steps) + " steps found in " +
      std::to_string(static_cast<long>(r.time_ms)) + " ms; smoothing");
  double said_ms = deadline.elapsedMs();
  options.progress = [&](int round, int checked, int windows, int refitted) {
    if (deadline.elapsedMs() - said_ms < 1000.0) return;
    said_ms = deadline.elapsedMs();
    say("team smoothing: repair round " + std::to_string(round) + ", " + std::to_string(refitted) +
        " agents refitted, " + std::to_string(checked) + " of " + std::to_string(windows) +
        " time windows checked, " +
        std::to_string(static_cast<long>(deadline.elapsedMs() / 1000.0)) + " s");
  };
  TeamTrajectories smooth = smoothTeamPaths(team, *problem.world, options);
  plan.counters["step_duration_s"] = options.step_duration;
  plan.counters["smoothing_ms"] = msSince(smoothing_start);
  plan.counters["repair_rounds"] = smooth.repair_rounds;
  plan.counters["stops_added"] = smooth.stops_added;
  plan.counters["pair_checks"] = static_cast<double>(smooth.pair_checks);
  plan.counters["planned_min_separation"] = smooth.min_separation;
  if (!smooth.success) {
    plan.status = smooth.status;
    plan.message = "no team trajectories: " + smooth.message;
    return;
  }
  plan.trajectories = std::move(smooth.trajectories);
  plan.success = true;
  plan.status = r.status;
}

// One prioritised search on a dense roadmap within `limit`, its result checked independently:
// every pair apart at every step and along every move, by all pairs.
DenseTeamResult searchDense(const TeamPlanningProblem& problem, const SeparationEllipsoid& e,
                            const DenseRoadmap& roadmap, const StopToken& limit) {
  DenseTeamQuery q;
  q.graph = &roadmap.graph;
  q.positions = &roadmap.positions;
  q.pitch = roadmap.grid.pitch();
  q.ellipsoid = e;
  q.separation = problem.min_separation;
  q.starts = roadmap.starts;
  q.goals = roadmap.goals;
  q.deadline = &limit;
  DenseTeamResult d = planDenseTeam(q);
  if (d.success &&
      closestLockStepDistance(d.paths, roadmap.positions, e) < problem.min_separation) {
    d.success = false;
    d.status = PlannerStatus::InvalidSolution;
    d.message = "a pair comes closer than the separation";
  }
  return d;
}

// The dense stage: starts or goals the team grid cannot hold, planned on a finer roadmap with
// ellipsoid conflicts (dense_roadmap.h, dense_team_search.h) whatever MAPF planner was named.
// A planar team gets half the time in its plane, then every layer is opened.
void planDense(const TeamPlanningProblem& problem, const SeparationEllipsoid& e, double inflation,
               const StopToken& deadline, const Say& say, TeamPlan& plan) {
  std::vector<Eigen::Vector3d> starts, goals;
  for (const auto& a : problem.agents) {
    starts.push_back(a.start);
    goals.push_back(a.goal);
  }
  const double search_start = deadline.elapsedMs();
  DenseRoadmap roadmap;
  DenseTeamResult d;
  for (const bool planar : {true, false}) {
    roadmap =
        denseRoadmap(*problem.world, starts, goals, e, problem.min_separation, inflation, planar);
    if (planar != roadmap.planar) continue;  // not a planar team: the open roadmap only
    say("team plan: " + std::to_string(starts.size()) +
        " agents closer than the team grid's cells: prioritised planning with ellipsoid "
        "conflicts on a roadmap of " +
        std::to_string(roadmap.graph.vertexCount()) + " vertices" + (planar ? " (one plane)" : ""));
    const double left_s = problem.time_limit_s - deadline.elapsedMs() / 1000.0;
    d = searchDense(problem, e, roadmap, StopToken(planar ? 0.5 * left_s : left_s, problem.stop));
    if (d.success || deadline.expired()) break;
  }
  const OccupancyGrid& cells = roadmap.grid.occupancy();
  plan.counters["grid_cells"] = static_cast<double>(cells.cellCount());
  plan.counters["blocked_cells"] = static_cast<double>(cells.blockedCount());
  plan.counters["pitch_xy_m"] = roadmap.grid.pitch().x();
  plan.counters["pitch_z_m"] = roadmap.grid.pitch().z();
  plan.counters["dense_roadmap_refinement"] = roadmap.refinement;
  plan.counters["dense_roadmap_planar"] = roadmap.planar ? 1 : 0;
  for (const auto& [k, v] : d.counters) plan.counters[k] = v;
  MapfResult r;
  r.time_ms = deadline.elapsedMs() - search_start;
  plan.counters["mapf_ms"] = r.time_ms;
  if (!d.success) {
    plan.status = d.status;
    plan.message = "no team plan on the dense roadmap: " + d.message;
    return;
  }
  for (const auto& p : d.paths) {
    r.paths.emplace_back();
    for (const int v : p) r.paths.back().push_back(roadmap.graph.cellOf(v));
  }
  r.success = true;
  r.status = d.status;
  plan.counters["sum_of_costs"] = static_cast<double>(sumOfCosts(r.paths));
  plan.counters["makespan"] = makespan(r.paths);
  smoothGrid(problem, roadmap.grid, r, deadline, say, plan);
}

// Whether every pair keeps the separation while all move from their points to their cells'
// centres at once (the plan's first and last steps).
bool snapsApart(const TeamGrid& grid, const std::vector<Eigen::Vector3d>& points,
                const std::vector<Cell>& cells, const SeparationEllipsoid& e, double separation) {
  for (std::size_t j = 1; j < points.size(); ++j)
    for (std::size_t i = 0; i < j; ++i)
      if (sweptEllipsoidDistance(e, points[i], grid.centre(cells[i]), points[j],
                                 grid.centre(cells[j])) < separation)
        return false;
  return true;
}

// The team grid's instance, or false when some start or goal shares a cell or lies in a blocked
// one, or the moves onto the cells come closer than the separation (then the dense roadmap is
// tried).
bool coarseInstance(const TeamGrid& grid, const TeamPlanningProblem& problem,
                    const SeparationEllipsoid& e, MapfInstance& instance) {
  try {
    instance = snappedInstance(grid, problem.agents);
  } catch (const InputError&) {
    return false;
  }
  std::vector<Eigen::Vector3d> starts, goals;
  for (const auto& a : problem.agents) {
    starts.push_back(a.start);
    goals.push_back(a.goal);
  }
  return snapsApart(grid, starts, instance.starts, e, problem.min_separation) &&
         snapsApart(grid, goals, instance.goals, e, problem.min_separation);
}

}  // namespace

TeamPlan planQuadrotorTeam(const TeamPlanningProblem& problem, MapfPlanner& planner) {
  const auto start = std::chrono::steady_clock::now();
  // One time limit and stop request for every stage.
  const StopToken deadline(problem.time_limit_s, problem.stop);
  const Say say = [&](const std::string& line) {
    if (problem.progress) problem.progress(line);
  };
  TeamPlan plan;
  const auto& agents = problem.agents;
  double inflation = 0.0;
  for (const auto& a : agents) inflation = std::max(inflation, a.inflation);
  const SeparationEllipsoid e = teamEllipsoid(agents);
  const Eigen::Vector3d pitch = std::sqrt(2.0) * problem.min_separation * kPitchRoundOff *
                                Eigen::Vector3d(e.radius, e.radius, e.height);
  const TeamGrid grid = TeamGrid::over(*problem.world, pitch, inflation);
  MapfInstance instance;
  if (!coarseInstance(grid, problem, e, instance)) {
    planDense(problem, e, inflation, deadline, say, plan);
    plan.time_ms = msSince(start);
    return plan;
  }
  plan.counters["grid_cells"] = static_cast<double>(instance.grid.cellCount());
  plan.counters["blocked_cells"] = static_cast<double>(instance.grid.blockedCount());
  plan.counters["pitch_xy_m"] = pitch.x();
  plan.counters["pitch_z_m"] = pitch.z();
  say("team plan: " + std::to_string(agents.size()) + " agents on a grid of " +
      std::to_string(instance.grid.cellCount()) + " cells with " + planner.name());
  MapfResult r;
  if (searchGrid(problem, planner, instance, deadline, plan, r)) {
    plan.counters["sum_of_costs"] = static_cast<double>(sumOfCosts(r.paths));
    plan.counters["makespan"] = makespan(r.paths);
    smoothGrid(problem, grid, r, deadline, say, plan);
  }
  plan.time_ms = msSince(start);
  return plan;
}

}  // namespace cosim
