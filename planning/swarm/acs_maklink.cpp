#include "planning/swarm/acs_maklink.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "core/input_error.h"

namespace cosim {

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();

// The colony over the offsets of the d lines Dijkstra's route crosses: `levels` candidate points
// on each line, the lengths of every hop between them, the pheromone, and the best tour T+.
class OffsetColony {
 public:
  OffsetColony(const MaklinkGraph& graph, const MaklinkRoute& route, const Eigen::Vector2d& start,
               const Eigen::Vector2d& goal, const AcsMaklinkParams& p, std::uint64_t seed)
      : p_(p),
        d_(static_cast<int>(route.lines.size())),
        L_(p.levels),
        s_(1.0 / (L_ - 1)),
        point_(d_, std::vector<Eigen::Vector2d>(L_)),
        hop_(d_ + 1, std::vector<double>(L_ * L_, kInf)),
        reference_(d_, 0.5),
        tau_(static_cast<std::size_t>(d_) * L_, p.tau0),
        tours_(p.ants, std::vector<int>(d_)),
        rng_(seed),
        weight_(L_) {
    for (int i = 0; i < d_; ++i)
      for (int j = 0; j < L_; ++j) point_[i][j] = graph.lines()[route.lines[i]].at(level(j));
    measureHops(graph, start, goal);
    // T+ starts as Dijkstra's midpoint path when the midpoint is one of the levels.
    best_.assign(d_, (L_ - 1) / 2);
    best_length_ = (L_ % 2 == 1) ? tourLength(best_) : kInf;
  }

  int lines() const { return d_; }
  double level(int j) const { return static_cast<double>(j) / (L_ - 1); }
  const Eigen::Vector2d& point(int i, int j) const { return point_[i][j]; }
  const std::vector<int>& best() const { return best_; }
  double bestLength() const { return best_length_; }

  // Tour t (1-based): every ant picks its offsets, then T+ and the pheromone are updated. Sets
  // best_iteration to t if T+ improved; true when all ants built the same tour (the colony stops).
  bool tour(int t, int& best_iteration) {
    // Synchronous tour: all ants choose on line 1, then all on line 2, ... (steps 4-8).
    for (int i = 0; i < d_; ++i)
      for (int k = 0; k < p_.ants; ++k) {
        const int chosen = chooseOffset(i, t);
        tours_[k][i] = chosen;
        double& tij = tau_[i * L_ + chosen];
        tij = (1.0 - p_.rho) * tij + p_.rho * p_.tau0;  // local update, eq. (3)
      }
    // Steps 10-11: lengths, the tour's best, T+.
    int tour_best = -1;
    double tour_best_length = kInf;
    for (int k = 0; k < p_.ants; ++k) {
      const double len = tourLength(tours_[k]);
      if (len < tour_best_length) tour_best_length = len, tour_best = k;
    }
    if (tour_best >= 0) {
      for (int i = 0; i < d_; ++i) reference_[i] = level(tours_[tour_best][i]);
      if (tour_best_length < best_length_ - 1e-12) {
        best_length_ = tour_best_length;
        best_ = tours_[tour_best];
        best_iteration = t;
      }
    }
    // Global update, eq. (2), on T+ (the ACS of Dorigo and Gambardella reinforces the best-so-far
    // tour; the seed's wording "best in this tour" is ambiguous).
    if (std::isfinite(best_length_))
      for (int i = 0; i < d_; ++i) {
        double& tij = tau_[i * L_ + best_[i]];
        tij = (1.0 - p_.rho) * tij + p_.rho / best_length_;
      }
    bool same = true;
    for (int k = 1; k < p_.ants && same; ++k) same = tours_[k] == tours_[0];
    return same;
  }

 private:
  // The lengths of every segment a tour can use (inf where a segment would leave free space: the
  // regions are convex in the seed's construction, but we do not rely on it).
  // hop_[i][j * L + k]: from node j of line i - 1 (i = 0: the start) to node k of line i;
  // hop_[d][j * L]: from node j of the last line to the goal.
  void measureHops(const MaklinkGraph& graph, const Eigen::Vector2d& start,
                   const Eigen::Vector2d& goal) {
    auto segment = [&](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
      return graph.segmentFree(a, b) ? (a - b).norm() : kInf;
    };
    if (d_ == 0) {
      hop_[0][0] = segment(start, goal);
      return;
    }
    for (int k = 0; k < L_; ++k) hop_[0][k] = segment(start, point_[0][k]);
    for (int i = 1; i < d_; ++i)
      for (int j = 0; j < L_; ++j)
        for (int k = 0; k < L_; ++k) hop_[i][j * L_ + k] = segment(point_[i - 1][j], point_[i][k]);
    for (int j = 0; j < L_; ++j) hop_[d_][j * L_] = segment(point_[d_ - 1][j], goal);
  }

  double tourLength(const std::vector<int>& h) const {
    if (d_ == 0) return hop_[0][0];
    double len = hop_[0][h[0]];
    for (int i = 1; i < d_; ++i) len += hop_[i][h[i - 1] * L_ + h[i]];
    return len + hop_[d_][h[d_ - 1] * L_];
  }

  // One ant's offset on line i in tour t: the pseudo-random proportional rule.
  int chooseOffset(int i, int t) {
    int chosen = 0, ties = 0;
    for (int j = 0; j < L_; ++j) {
      // Before the first tour there is no best path to be near: every option is as visible.
      const double eta =
          t == 1 ? 1.0 : (1.0 + s_ - std::fabs(level(j) - reference_[i])) / (1.0 + s_);
      weight_[j] = tau_[i * L_ + j] * std::pow(eta, p_.beta);
      // argmax, ties broken uniformly (all options tie in the first tour).
      if (j == 0 || weight_[j] > weight_[chosen] * (1 + 1e-12)) {
        chosen = j;
        ties = 1;
      } else if (weight_[j] >= weight_[chosen] * (1 - 1e-12) &&
                 std::uniform_int_distribution<int>(0, ties++)(rng_) == 0) {
        chosen = j;
      }
    }
    if (unit_(rng_) > p_.q0) {  // exploration: roulette of eq. (1)
      double total = 0.0;
      for (double w : weight_) total += w;
      double r = unit_(rng_) * total;
      for (chosen = 0; chosen + 1 < L_; ++chosen) {
        r -= weight_[chosen];
        if (r < 0.0) break;
      }
    }
    return chosen;
  }

  const AcsMaklinkParams& p_;
  const int d_, L_;
  const double s_;
  std::vector<std::vector<Eigen::Vector2d>> point_;
  std::vector<std::vector<double>> hop_;
  std::vector<int> best_;
  double best_length_ = kInf;
  std::vector<double> reference_;  // y* of the visibility: last tour's best offsets
  std::vector<double> tau_;
  std::vector<std::vector<int>> tours_;
  std::mt19937_64 rng_;
  std::uniform_real_distribution<double> unit_{0.0, 1.0};
  std::vector<double> weight_;
};

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
  OffsetColony colony(graph, route, start, goal, p, seed);
  const int d = colony.lines();
  out.crossed = d;
  out.dijkstra_length = route.length;
  int t = 0;
  while (d > 0 && t < p.iterations && !deadline.expired()) {
    ++t;
    const bool converged = colony.tour(t, out.best_iteration);
    out.history.push_back(colony.bestLength());
    if (converged) break;
  }
  out.iterations = t;

  if (!std::isfinite(colony.bestLength())) {
    out.message = "no collision-free tour over the offsets (time limit?)";
    out.status = searchStatus(false, deadline, PlannerStatus::NoSolution);
    out.time_ms = deadline.elapsedMs();
    return out;
  }
  out.success = true;
  out.status = searchStatus(true, deadline, PlannerStatus::NoSolution);
  out.length = colony.bestLength();
  out.path.push_back(start);
  for (int i = 0; i < d; ++i) {
    out.offsets.push_back(colony.level(colony.best()[i]));
    out.path.push_back(colony.point(i, colony.best()[i]));
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
      "the ant-algorithm lecture's hybrid ACS: MAKLINK graph of grown polygons, Dijkstra, ant colony "
      "system over "
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
