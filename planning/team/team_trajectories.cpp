#include "planning/team/team_trajectories.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "planning/team/team_pair_candidates.h"
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

// The first and last piece where two fits of one agent differ ({1, 0}: none). Both have one
// piece per step, so piece k covers [k step, (k + 1) step] in each.
std::pair<long, long> changedPieces(const PiecewisePolynomialTrajectory& a,
                                    const PiecewisePolynomialTrajectory& b) {
  long first = 1, last = 0;
  const auto& pa = a.pieces();
  const auto& pb = b.pieces();
  for (std::size_t k = 0; k < std::max(pa.size(), pb.size()); ++k) {
    const bool same_piece = k < pa.size() && k < pb.size() && pa[k].duration == pb[k].duration &&
                            pa[k].coefficients == pb[k].coefficients;
    if (same_piece) continue;
    if (first > last) first = static_cast<long>(k);
    last = static_cast<long>(k);
  }
  return {first, last};
}

constexpr double kInf = std::numeric_limits<double>::infinity();
// The spatial hash finds the pairs within this many separations: more than one, so that the
// closest approach reported is the true one whenever it is anywhere near the separation.
constexpr double kReachInSeparations = 1.5;

// The check and repair, window by window: what each window's last check found is kept, and a
// window is checked again only when a trajectory changed inside it.
class TeamSmoother {
 public:
  TeamSmoother(const std::vector<TeamMember>& team, const World& world,
               const TeamTrajectoryOptions& o, TeamTrajectories& out)
      : team_(team), world_(world), o_(o), out_(out), n_(team.size()) {}

  void run();

 private:
  bool expired() const { return o_.deadline != nullptr && o_.deadline->expired(); }
  bool fitAll();             // false: stopped or out of time before every agent was fitted
  bool checkWindow(long w);  // false: stopped or out of time (the window stays to be checked)
  void stopNear(std::size_t i, double t);
  int refit();  // rebuilds the changed agents, marks the windows they changed; returns how many
  void summarise();
  void endExpired();

  const std::vector<TeamMember>& team_;
  const World& world_;
  const TeamTrajectoryOptions& o_;
  TeamTrajectories& out_;
  std::size_t n_;
  std::vector<std::vector<char>> stops_;
  double end_ = 0.0;
  long instants_ = 0, per_window_ = 1, windows_ = 0;
  Eigen::Vector3d scale_ = Eigen::Vector3d::Ones();
  std::vector<std::vector<Eigen::Vector3d>> at_;  // agent x instant
  // A window is checked again when a trajectory changed in it or its last check found a
  // violation (whose repair may have changed nothing inside it).
  std::vector<char> window_dirty_, window_violated_, changed_;
  // This round, per agent: its stops when the round began (once it has changed) and the runs
  // between those stops it has been given a new stop in (first and last waypoint). A stop in
  // one run changes only that run's fit, so violations in other runs are repaired in the same
  // round; a later violation in a run already changed waits for the refit.
  std::vector<std::vector<char>> round_stops_;
  std::vector<std::vector<std::pair<long, long>>> touched_;
  std::vector<double> window_separation_;  // per window, its last check's
  // Per agent and window (agent-major): the clearance its last check found, and whether its
  // trajectory changed there since (obstacle distances are most of a check's cost).
  std::vector<double> clearance_;
  std::vector<char> resampled_;
  // Per window: the pairs its last check evaluated (sorted) and each one's closest approach
  // there; a pair whose members both kept their trajectory in the window keeps its figure.
  std::vector<std::vector<std::pair<int, int>>> pairs_;
  std::vector<std::vector<double>> pair_min_;
};

// The loops below look at the deadline for every agent (fitting or sampling one costs far more
// than reading the clock) and every few dozen pairs: one pass over a 500-agent team takes seconds
// on a slow (or sanitized) build, and a stop request must end the stage within a second.
constexpr std::size_t kPairsBetweenDeadlineChecks = 64;

bool TeamSmoother::fitAll() {
  stops_.resize(n_);
  double radius = 0.0, height = 0.0;
  for (std::size_t i = 0; i < n_; ++i) {
    if (expired()) return false;
    stops_[i].assign(team_[i].points.size(), 0);
    stops_[i].front() = stops_[i].back() = 1;
    for (const long k : team_[i].rest_steps)
      if (k >= 0 && k < static_cast<long>(stops_[i].size())) stops_[i][k] = 1;
    out_.trajectories.push_back(build(team_[i].points, stops_[i], o_.step_duration));
    end_ = std::max(end_, out_.trajectories.back().duration());
    radius = std::max(radius, team_[i].separation.radius);
    height = std::max(height, team_[i].separation.height);
  }
  // Every pair's ellipsoid is at most the team's largest: in these units no pair is closer
  // than its scaled Euclidean distance.
  scale_ = Eigen::Vector3d(1.0 / radius, 1.0 / radius, 1.0 / height);
  instants_ = static_cast<long>(std::ceil(end_ / o_.check_interval));
  per_window_ = std::max(1L, static_cast<long>(std::ceil(o_.step_duration / o_.check_interval)));
  windows_ = instants_ / per_window_ + 1;
  at_.assign(n_, std::vector<Eigen::Vector3d>(instants_ + 1));
  for (std::size_t i = 0; i < n_; ++i) {
    if (expired()) return false;
    for (long s = 0; s <= instants_; ++s)
      at_[i][s] = out_.trajectories[i].sample(std::min(end_, s * o_.check_interval)).position;
  }
  window_dirty_.assign(windows_, 1);
  window_violated_.assign(windows_, 0);
  window_separation_.assign(windows_, kInf);
  clearance_.assign(n_ * windows_, kInf);
  resampled_.assign(n_ * windows_, 1);
  pairs_.assign(windows_, {});
  pair_min_.assign(windows_, {});
  changed_.assign(n_, 0);
  round_stops_.resize(n_);
  touched_.resize(n_);
  return true;
}

void TeamSmoother::stopNear(std::size_t i, double t) {
  auto& stop = stops_[i];
  const auto n = static_cast<long>(stop.size());
  const long before = std::clamp(static_cast<long>(std::floor(t / o_.step_duration)), 0L, n - 1);
  const long after = std::min(before + 1, n - 1);
  for (const auto& [a, b] : touched_[i])
    if (before >= a && after <= b) return;
  if (stop[before] && stop[after]) return;  // nothing left to change here
  if (!changed_[i]) round_stops_[i] = stop;
  const auto& was = round_stops_[i];
  long a = before, b = after;
  while (a > 0 && !was[a]) --a;
  while (b < n - 1 && !was[b]) ++b;
  touched_[i].emplace_back(a, b);
  for (const long k : {before, after})
    if (!stop[k]) stop[k] = 1, ++out_.stops_added;
  changed_[i] = 1;
}

bool TeamSmoother::checkWindow(long w) {
  const long first = w * per_window_;
  const long last = std::min(instants_, first + per_window_ - 1);
  const auto fresh = [&](int i) { return resampled_[static_cast<std::size_t>(i) * windows_ + w]; };
  double clearance = kInf;
  for (std::size_t i = 0; i < n_; ++i) {
    if (expired()) return false;
    double& c = clearance_[i * windows_ + w];
    if (fresh(static_cast<int>(i))) {
      c = kInf;
      for (long s = first; s <= last; ++s) {
        const double clear = world_.distanceToObstacles(at_[i][s]) - team_[i].clearance;
        c = std::min(c, clear);
        if (clear < 0.0) stopNear(i, std::min(end_, s * o_.check_interval));
      }
    }
    clearance = std::min(clearance, c);
  }
  auto pairs = candidatePairs(at_, first, last, scale_, kReachInSeparations * o_.min_separation);
  std::vector<double> pair_min(pairs.size(), kInf);
  const auto& old_pairs = pairs_[w];
  double separation = kInf;
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    if (k % kPairsBetweenDeadlineChecks == 0 && expired()) return false;
    const auto [i, j] = pairs[k];
    if (!fresh(i) && !fresh(j)) {
      const auto it = std::lower_bound(old_pairs.begin(), old_pairs.end(), pairs[k]);
      const std::size_t o = static_cast<std::size_t>(it - old_pairs.begin());
      if (it != old_pairs.end() && *it == pairs[k] && pair_min_[w][o] >= o_.min_separation) {
        pair_min[k] = pair_min_[w][o];
        separation = std::min(separation, pair_min[k]);
        continue;
      }
    }
    const SeparationEllipsoid e =
        SeparationEllipsoid::between(team_[i].separation, team_[j].separation);
    for (long s = first; s <= last; ++s) {
      const double d = e.distance(at_[i][s], at_[j][s]);
      pair_min[k] = std::min(pair_min[k], d);
      if (d >= o_.min_separation) continue;
      const double t = std::min(end_, s * o_.check_interval);
      stopNear(i, t);
      stopNear(j, t);
    }
    out_.pair_checks += last - first + 1;
    separation = std::min(separation, pair_min[k]);
  }
  for (std::size_t i = 0; i < n_; ++i) resampled_[i * windows_ + w] = 0;
  pairs_[w] = std::move(pairs);
  pair_min_[w] = std::move(pair_min);
  window_separation_[w] = separation;
  window_violated_[w] = separation < o_.min_separation || clearance < 0.0;
  return true;
}

int TeamSmoother::refit() {
  int refitted = 0;
  window_dirty_ = window_violated_;
  for (std::size_t i = 0; i < n_; ++i) {
    if (!changed_[i]) continue;
    ++refitted;
    PiecewisePolynomialTrajectory fit = build(team_[i].points, stops_[i], o_.step_duration);
    const auto [first, last] = changedPieces(out_.trajectories[i], fit);
    out_.trajectories[i] = std::move(fit);
    if (first > last) continue;
    const long s0 = static_cast<long>(std::floor(first * o_.step_duration / o_.check_interval));
    const long s1 = std::min(
        instants_, static_cast<long>(std::ceil((last + 1) * o_.step_duration / o_.check_interval)));
    for (long s = s0; s <= s1; ++s)
      at_[i][s] = out_.trajectories[i].sample(std::min(end_, s * o_.check_interval)).position;
    for (long w = s0 / per_window_; w <= s1 / per_window_ && w < windows_; ++w)
      window_dirty_[w] = resampled_[i * windows_ + w] = 1;
    if (expired()) break;
  }
  std::fill(changed_.begin(), changed_.end(), 0);
  for (auto& runs : touched_) runs.clear();
  return refitted;
}

void TeamSmoother::summarise() {
  // No pair within the hash's reach: that reach is what is known (a lower bound).
  out_.min_separation =
      std::min(kReachInSeparations * o_.min_separation,
               *std::min_element(window_separation_.begin(), window_separation_.end()));
  out_.min_clearance = *std::min_element(clearance_.begin(), clearance_.end());
}

void TeamSmoother::endExpired() {
  summarise();
  out_.status = expiredStatus(*o_.deadline);
  out_.message = out_.status == PlannerStatus::Stopped ? "stopped" : "time limit reached";
}

void TeamSmoother::run() {
  if (!fitAll()) {  // nothing checked yet: no separation or clearance to report
    out_.status = expiredStatus(*o_.deadline);
    out_.message = out_.status == PlannerStatus::Stopped ? "stopped" : "time limit reached";
    return;
  }
  for (out_.repair_rounds = 0; out_.repair_rounds <= o_.max_repair_rounds; ++out_.repair_rounds) {
    int checked = 0;
    for (long w = 0; w < windows_; ++w) {
      if (!window_dirty_[w]) continue;
      if (expired() || !checkWindow(w)) return endExpired();
      ++checked;
    }
    if (std::none_of(changed_.begin(), changed_.end(), [](char c) { return c; })) {
      // Nothing more to repair: what is still violated, the grid plan itself violates.
      summarise();
      out_.success = out_.min_separation >= o_.min_separation && out_.min_clearance >= 0.0;
      out_.status = out_.success ? PlannerStatus::ExactSolution : PlannerStatus::NoSolution;
      if (!out_.success)
        out_.message = "the grid plan itself comes closer than the separation (minimum " +
                       std::to_string(out_.min_separation) + ") or the clearance";
      return;
    }
    const int refitted = refit();
    if (expired()) return endExpired();
    if (o_.progress)
      o_.progress(out_.repair_rounds + 1, checked, static_cast<int>(windows_), refitted);
  }
  summarise();
  out_.message = "the separation could not be kept within " + std::to_string(o_.max_repair_rounds) +
                 " repair rounds";
  out_.status = PlannerStatus::LimitReached;
}

}  // namespace

TeamTrajectories smoothTeamPaths(const std::vector<TeamMember>& team, const World& world,
                                 const TeamTrajectoryOptions& options) {
  TeamTrajectories out;
  for (const TeamMember& m : team)
    if (m.points.empty()) {
      out.message = "an agent has no path";
      out.status = PlannerStatus::InvalidProblem;
      return out;
    }
  if (team.empty()) {
    out.success = true;
    out.status = PlannerStatus::ExactSolution;
    return out;
  }
  TeamSmoother(team, world, options, out).run();
  return out;
}

}  // namespace cosim
