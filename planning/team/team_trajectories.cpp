#include "planning/team/team_trajectories.h"

#include <algorithm>
#include <cmath>

#include "planning/trajectory/minimum_snap_closed_form.h"

namespace cosim {

namespace {

bool same(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return (a - b).norm() < 1e-9;
}

PolynomialPiece hold(const Eigen::Vector3d& p, double duration) {
  PolynomialPiece piece;
  piece.duration = duration;
  piece.coefficients.row(0) = p.transpose();
  return piece;
}

// One agent's trajectory: rest at every stop (and at its ends and waits), one minimum-snap
// polynomial through the waypoints of each run between stops, every segment `step` long.
PiecewisePolynomialTrajectory build(const std::vector<Eigen::Vector3d>& p,
                                    const std::vector<char>& stop, double step) {
  std::vector<PolynomialPiece> pieces;
  std::size_t k = 0;
  while (k + 1 < p.size()) {
    if (same(p[k], p[k + 1])) {  // a wait
      pieces.push_back(hold(p[k], step));
      ++k;
      continue;
    }
    std::size_t j = k + 1;
    while (j + 1 < p.size() && !stop[j] && !same(p[j], p[j + 1])) ++j;
    const MinimumSnapClosedForm fit(std::vector<Eigen::Vector3d>(p.begin() + k, p.begin() + j + 1));
    const PiecewisePolynomialTrajectory run = fit.trajectory(std::vector<double>(j - k, step));
    pieces.insert(pieces.end(), run.pieces().begin(), run.pieces().end());
    k = j;
  }
  if (pieces.empty()) pieces.push_back(hold(p.front(), step));
  return PiecewisePolynomialTrajectory(std::move(pieces));
}

// Makes an agent stop at the waypoints before and after instant t; returns how many stops that
// added (0: it already stops at both).
int stopAround(std::vector<char>& stop, double t, double step) {
  const auto n = static_cast<long>(stop.size());
  const long before = std::clamp(static_cast<long>(std::floor(t / step)), 0L, n - 1);
  const long after = std::min(before + 1, n - 1);
  int added = 0;
  for (long k : {before, after}) {
    if (!stop[k]) stop[k] = 1, ++added;
  }
  return added;
}

}  // namespace

TeamTrajectories smoothTeamPaths(const std::vector<TeamMember>& team, const World& world,
                                 const TeamTrajectoryOptions& o) {
  TeamTrajectories out;
  const std::size_t n = team.size();
  std::vector<std::vector<char>> stops(n);
  for (std::size_t i = 0; i < n; ++i) {
    if (team[i].points.empty()) {
      out.message = "an agent has no path";
      out.status = PlannerStatus::InvalidProblem;
      return out;
    }
    stops[i].assign(team[i].points.size(), 0);
    stops[i].front() = stops[i].back() = 1;
    out.trajectories.push_back(build(team[i].points, stops[i], o.step_duration));
  }

  // Only what a round rebuilt is checked again: a pair neither of whose trajectories changed was
  // checked whole in the round before (a pair is skipped at an instant only when both members
  // are being rebuilt), so its closest approach, kept per pair, still holds.
  std::vector<char> dirty(n, 1);
  std::vector<std::vector<Eigen::Vector3d>> at(n);
  std::vector<double> pair_min(n * n, std::numeric_limits<double>::infinity());
  std::vector<double> clear_min(n, std::numeric_limits<double>::infinity());
  for (out.repair_rounds = 0; out.repair_rounds <= o.max_repair_rounds; ++out.repair_rounds) {
    double end = 0.0;
    for (const auto& t : out.trajectories) end = std::max(end, t.duration());
    const long instants = static_cast<long>(std::ceil(end / o.check_interval));
    for (std::size_t i = 0; i < n; ++i)
      if (at[i].size() != static_cast<std::size_t>(instants + 1)) dirty[i] = 1;
    std::vector<std::pair<std::size_t, std::size_t>> pairs;
    for (std::size_t i = 0; i < n; ++i) {
      if (dirty[i]) {
        at[i].resize(instants + 1);
        for (long s = 0; s <= instants; ++s)
          at[i][s] = out.trajectories[i].sample(std::min(end, s * o.check_interval)).position;
        clear_min[i] = std::numeric_limits<double>::infinity();
      }
      for (std::size_t j = i + 1; j < n; ++j)
        if (dirty[i] || dirty[j]) {
          pairs.emplace_back(i, j);
          pair_min[i * n + j] = std::numeric_limits<double>::infinity();
        }
    }
    std::vector<char> changed(n, 0);
    const auto stopNear = [&](std::size_t i, double t) {
      const int added = stopAround(stops[i], t, o.step_duration);
      out.stops_added += added;
      return added > 0;
    };
    for (long s = 0; s <= instants; ++s) {
      const double t = std::min(end, s * o.check_interval);
      for (std::size_t i = 0; i < n; ++i) {
        if (!dirty[i]) continue;
        const double clear = world.distanceToObstacles(at[i][s]) - team[i].clearance;
        clear_min[i] = std::min(clear_min[i], clear);
        if (clear < 0.0 && !changed[i]) changed[i] = stopNear(i, t);
      }
      for (const auto& [i, j] : pairs) {
        const double d = SeparationEllipsoid::between(team[i].separation, team[j].separation)
                             .distance(at[i][s], at[j][s]);
        pair_min[i * n + j] = std::min(pair_min[i * n + j], d);
        if (d >= o.min_separation || (changed[i] && changed[j])) continue;
        if (!changed[i]) changed[i] = stopNear(i, t);
        if (!changed[j]) changed[j] = stopNear(j, t);
      }
    }
    out.min_separation = out.min_clearance = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < n; ++i) {
      out.min_clearance = std::min(out.min_clearance, clear_min[i]);
      for (std::size_t j = i + 1; j < n; ++j)
        out.min_separation = std::min(out.min_separation, pair_min[i * n + j]);
    }
    if (std::none_of(changed.begin(), changed.end(), [](char c) { return c; })) {
      // Nothing more to repair: what is still violated, the grid plan itself violates.
      out.success = out.min_separation >= o.min_separation && out.min_clearance >= 0.0;
      out.status = out.success ? PlannerStatus::ExactSolution : PlannerStatus::NoSolution;
      if (!out.success)
        out.message = "the grid plan itself comes closer than the separation (minimum " +
                      std::to_string(out.min_separation) + ") or the clearance";
      return out;
    }
    for (std::size_t i = 0; i < n; ++i)
      if (changed[i]) out.trajectories[i] = build(team[i].points, stops[i], o.step_duration);
    dirty = changed;
  }
  out.message = "the separation could not be kept within " + std::to_string(o.max_repair_rounds) +
                " repair rounds";
  out.status = PlannerStatus::LimitReached;
  return out;
}

}  // namespace cosim
