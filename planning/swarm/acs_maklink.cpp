#include "planning/swarm/acs_maklink.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "core/input_error.h"

namespace cosim {

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
}  // namespace

AcsMaklinkResult optimiseMaklinkRoute(const MaklinkGraph& graph, const Eigen::Vector2d& start,
                                      const Eigen::Vector2d& goal, const AcsMaklinkParams& p,
                                      std::uint64_t seed, const StopToken& deadline) {
  AcsMaklinkResult out;
  out.lines = static_cast<int>(graph.lines().size());
  if (!graph.pointFree(start) || !graph.pointFree(goal)) {
    out.message = std::string(graph.pointFree(start) ? "goal" : "start") +
                  " is inside a grown obstacle or outside the walls";
    out.status = graph.pointFree(start) ? PlannerStatus::InvalidGoal : PlannerStatus::InvalidStart;
    out.time_ms = deadline.elapsedMs();
    return out;
  }
  const MaklinkRoute route = graph.shortestRoute(start, goal);
  if (!route.found) {
    out.message = "goal unreachable: no route in the MAKLINK graph";
    out.status = PlannerStatus::NoSolution;
    out.time_ms = deadline.elapsedMs();
    return out;
  }
  const int d = static_cast<int>(route.lines.size());
  const int L = p.levels;
  out.crossed = d;
  out.dijkstra_length = route.length;
  auto level = [&](int j) { return static_cast<double>(j) / (L - 1); };

  // Candidate points and the lengths of every segment a tour can use (inf where a segment would
  // leave free space: the regions are convex in the seed's construction, but we do not rely on
  // it).
  std::vector<std::vector<Eigen::Vector2d>> point(d, std::vector<Eigen::Vector2d>(L));
  for (int i = 0; i < d; ++i)
    for (int j = 0; j < L; ++j) point[i][j] = graph.lines()[route.lines[i]].at(level(j));
  auto segment = [&](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return graph.segmentFree(a, b) ? (a - b).norm() : kInf;
  };
  // hop[i][j * L + k]: from node j of line i - 1 (i = 0: the start) to node k of line i;
  // hop[d][j * L]: from node j of the last line to the goal.
  std::vector<std::vector<double>> hop(d + 1, std::vector<double>(L * L, kInf));
  if (d == 0) {
    hop[0][0] = segment(start, goal);
  } else {
    for (int k = 0; k < L; ++k) hop[0][k] = segment(start, point[0][k]);
    for (int i = 1; i < d; ++i)
      for (int j = 0; j < L; ++j)
        for (int k = 0; k < L; ++k) hop[i][j * L + k] = segment(point[i - 1][j], point[i][k]);
    for (int j = 0; j < L; ++j) hop[d][j * L] = segment(point[d - 1][j], goal);
  }
  auto tourLength = [&](const std::vector<int>& h) {
    if (d == 0) return hop[0][0];
    double len = hop[0][h[0]];
    for (int i = 1; i < d; ++i) len += hop[i][h[i - 1] * L + h[i]];
    return len + hop[d][h[d - 1] * L];
  };

  // T+ starts as Dijkstra's midpoint path when the midpoint is one of the levels.
  std::vector<int> best(d, (L - 1) / 2);
  double best_length = (L % 2 == 1) ? tourLength(best) : kInf;
  std::vector<double> reference(d, 0.5);  // y* of the visibility: last tour's best offsets
  std::vector<double> tau(static_cast<std::size_t>(d) * L, p.tau0);
  std::vector<std::vector<int>> tours(p.ants, std::vector<int>(d));
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<double> weight(L);
  const double s = 1.0 / (L - 1);

  int t = 0;
  while (d > 0 && t < p.iterations && !deadline.expired()) {
    ++t;
    // Synchronous tour: all ants choose on line 1, then all on line 2, ... (steps 4-8).
    for (int i = 0; i < d; ++i)
      for (int k = 0; k < p.ants; ++k) {
        int chosen = 0, ties = 0;
        for (int j = 0; j < L; ++j) {
          // Before the first tour there is no best path to be near: every option is as visible.
          const double eta =
              t == 1 ? 1.0 : (1.0 + s - std::fabs(level(j) - reference[i])) / (1.0 + s);
          weight[j] = tau[i * L + j] * std::pow(eta, p.beta);
          // argmax, ties broken uniformly (all options tie in the first tour).
          if (j == 0 || weight[j] > weight[chosen] * (1 + 1e-12)) {
            chosen = j;
            ties = 1;
          } else if (weight[j] >= weight[chosen] * (1 - 1e-12) &&
                     std::uniform_int_distribution<int>(0, ties++)(rng) == 0) {
            chosen = j;
          }
        }
        if (unit(rng) > p.q0) {  // exploration: roulette of eq. (1)
          double total = 0.0;
          for (double w : weight) total += w;
          double r = unit(rng) * total;
          for (chosen = 0; chosen + 1 < L; ++chosen) {
            r -= weight[chosen];
            if (r < 0.0) break;
          }
        }
        tours[k][i] = chosen;
        double& tij = tau[i * L + chosen];
        tij = (1.0 - p.rho) * tij + p.rho * p.tau0;  // local update, eq. (3)
      }
    // Steps 10-11: lengths, the tour's best, T+.
    int tour_best = -1;
    double tour_best_length = kInf;
    for (int k = 0; k < p.ants; ++k) {
      const double len = tourLength(tours[k]);
      if (len < tour_best_length) tour_best_length = len, tour_best = k;
    }
    if (tour_best >= 0) {
      for (int i = 0; i < d; ++i) reference[i] = level(tours[tour_best][i]);
      if (tour_best_length < best_length - 1e-12) {
        best_length = tour_best_length;
        best = tours[tour_best];
        out.best_iteration = t;
      }
    }
    // Global update, eq. (2), on T+ (the ACS of Dorigo and Gambardella reinforces the best-so-far
    // tour; the seed's wording "best in this tour" is ambiguous).
    if (std::isfinite(best_length))
      for (int i = 0; i < d; ++i) {
        double& tij = tau[i * L + best[i]];
        tij = (1.0 - p.rho) * tij + p.rho / best_length;
      }
    out.history.push_back(best_length);
    bool same = true;
    for (int k = 1; k < p.ants && same; ++k) same = tours[k] == tours[0];
    if (same) break;
  }
  out.iterations = t;

  if (!std::isfinite(best_length)) {
    out.message = "no collision-free tour over the offsets (time limit?)";
    out.status = searchStatus(false, deadline, PlannerStatus::NoSolution);
    out.time_ms = deadline.elapsedMs();
    return out;
  }
  out.success = true;
  out.status = searchStatus(true, deadline, PlannerStatus::NoSolution);
  out.length = best_length;
  out.path.push_back(start);
  for (int i = 0; i < d; ++i) {
    out.offsets.push_back(level(best[i]));
    out.path.push_back(point[i][best[i]]);
  }
  out.path.push_back(goal);
  out.time_ms = deadline.elapsedMs();
  return out;
}

PlanResult AcsMaklink::solve(const PlanningProblem& problem, const StopToken& stop) {
  const StopToken deadline(problem.time_limit_s, stop);
  PlanResult result;
  const World& world = *problem.world;
  const double z = problem.start.z();
  const Eigen::Vector2d lo = world.bounds_min.head<2>().array() + problem.inflation;
  const Eigen::Vector2d hi = world.bounds_max.head<2>().array() - problem.inflation;
  const MaklinkGraph graph(planarObstacles(world, z, problem.inflation, p_.circle_sides), lo, hi,
                           &deadline);
  if (!graph.complete()) {
    result.message = "time limit reached while building the MAKLINK graph";
    result.status = expiredStatus(deadline);
    result.time_ms = deadline.elapsedMs();
    return result;
  }
  const AcsMaklinkResult r = optimiseMaklinkRoute(
      graph, problem.start.head<2>(), problem.goal.head<2>(), p_, problem.seed, deadline);
  result.counters["lines"] = r.lines;
  result.counters["nodes"] = r.lines + 2;
  result.counters["crossed_lines"] = r.crossed;
  result.counters["iterations"] = r.iterations;
  result.counters["best_iteration"] = r.best_iteration;
  result.counters["dijkstra_length_m"] = r.dijkstra_length;
  result.message = r.message;
  result.status = r.status;
  if (r.success) {
    for (const Eigen::Vector2d& q : r.path) result.path.waypoints.push_back({q.x(), q.y(), z});
    const Eigen::Vector3d top = result.path.waypoints.back();
    if (!problem.planar && std::fabs(problem.goal.z() - z) > 1e-9) {
      // The plane is left only at the goal's column: climb or descend to it, checked against
      // the exact obstacles (samples 1 cm apart, each needing the inflation's clearance).
      const int samples = 1 + static_cast<int>(std::ceil(std::fabs(problem.goal.z() - z) / 0.01));
      for (int k = 0; k <= samples; ++k) {
        const Eigen::Vector3d q = top + (problem.goal - top) * (static_cast<double>(k) / samples);
        if (world.distanceToObstacles(q) < problem.inflation) {
          result.message =
              "acs_maklink plans at the start's height; the vertical climb to the "
              "goal's height is blocked";
          result.status = PlannerStatus::InvalidGoal;
          result.path.waypoints.clear();
          result.time_ms = deadline.elapsedMs();
          return result;
        }
      }
      result.path.waypoints.push_back(problem.goal);
    }
    result.success = true;
  }
  result.time_ms = deadline.elapsedMs();
  return result;
}

void registerAcsMaklinkPlanner(PlannerRegistry& r) {
  PlannerEntry e;
  e.name = "acs_maklink";
  e.family = "swarm";
  e.summary =
      "seed 002 hybrid ACS: MAKLINK graph of grown polygons, Dijkstra, ant colony system over "
      "offsets along the crossed free lines (plans in the plane at the start's height)";
  e.make = [](ParamSet& params) -> std::unique_ptr<Planner> {
    AcsMaklinkParams p;
    p.beta = params.getDouble("beta", p.beta, 0.0, 20.0);
    p.q0 = params.getDouble("q0", p.q0, 0.0, 1.0);
    p.rho = params.getDouble("rho", p.rho, 1e-9, 1.0);
    p.tau0 = params.getDouble("tau0", p.tau0, 1e-12, 1e6);
    p.ants = params.getInt("ants", p.ants, 1, 10000);
    p.iterations = params.getInt("iterations", p.iterations, 1, 1000000);
    p.levels = params.getInt("levels", p.levels, 2, 1001);
    p.circle_sides = params.getInt("circle_sides", p.circle_sides, 3, 64);
    return std::make_unique<AcsMaklink>(p);
  };
  r.add(std::move(e));
}

}  // namespace cosim
