#include "planning/swarm/msac.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "core/stop_token.h"
#include "planning/swarm/ant_path_processing.h"

namespace cosim {

namespace {

// One MSAC search (seed 000 §2.3 steps 1-7 with the §4.3 modifications).
class MsacSearch {
 public:
  MsacSearch(const MsacParams& p, const AntGridView& grid, int start, int goal, std::uint64_t seed)
      : p_(p),
        grid_(grid),
        start_(start),
        goal_(goal),
        m_(p.ants),
        rng_(seed),
        tabu_(grid.cellCount(), 0),
        dead_(grid.cellCount(), 0),
        processing_(grid),
        paths_(2 * p.ants),
        walked_(2 * p.ants) {
    // No path is shorter than the obstacle-free distance of the move set (octile).
    const double dx = std::abs(grid.x(start) - grid.x(goal)),
                 dy = std::abs(grid.y(start) - grid.y(goal));
    lower_bound_ = std::max(dx, dy) + (AntGridView::kSqrt2 - 1.0) * std::min(dx, dy);
  }

  // Runs up to MAX iterations; returns the best path (empty if none).
  std::vector<int> run(const StopToken& deadline, int s_max, GridPlanResult& result) {
    best_length_ = std::numeric_limits<double>::infinity();
    best_.clear();
    int iterations = 0;
    long long steps = 0;
    for (int n = 0; n < p_.iterations && !deadline.expired(); ++n) {
      startIteration();
      if (best_length_ <= lower_bound_ + 1e-9) break;  // provably optimal: nothing to improve
      for (int s = 1; s <= s_max; ++s) {
        if ((s & 63) == 0 && deadline.expired()) break;
        ++steps;
        for (int a = 0; a < 2 * m_; ++a) moveAnt(a);
        const bool improved = checkMeetings();
        if (met_ && p_.iteration_end == MsacIterationEnd::Meeting) break;  // §4.3: groups met
        if (improved) break;  // a shorter path ends the iteration (step 6 -> 7)
      }
      ++iterations;
      endIteration();
    }
    result.counters["iterations"] = iterations;
    result.counters["steps"] = static_cast<double>(steps);
    result.counters["expansions"] = static_cast<double>(moves_);
    result.counters["meetings"] = static_cast<double>(meetings_);
    result.counters["dead_end_marks"] = static_cast<double>(dead_marks_);
    return best_;
  }

 private:
  int group(int ant) const { return ant < m_ ? 0 : 1; }
  int target(int ant) const { return group(ant) == 0 ? goal_ : start_; }
  // What ant writes into the tabu table for the cells it explores first.
  unsigned char tabuCode(int ant) const {
    if (p_.tabu_version == 1) return 1;
    if (p_.tabu_version == 2) return static_cast<unsigned char>(group(ant) + 1);
    // v3: 1..127 group 1 (ant id), 129..255 group 2 (ant id + 128).
    return static_cast<unsigned char>(group(ant) == 0 ? ant + 1 : 128 + (ant - m_) + 1);
  }
  int pick(int n) { return static_cast<int>((rng_() >> 11) % static_cast<std::uint64_t>(n)); }

  void startIteration() {
    std::fill(tabu_.begin(), tabu_.end(), 0);
    for (int a = 0; a < 2 * m_; ++a) {
      paths_[a].assign(1, group(a) == 0 ? start_ : goal_);
      walked_[a].assign(1, 0.0);
    }
    in_contact_.assign(2 * m_, false);
    tabu_[start_] = tabuCode(0);
    tabu_[goal_] = tabuCode(m_);
  }

  void endIteration() {
    // §4.3.2: dead-end marks carry over only if they block neither end (else the ants there
    // would have no move in the next iteration).
    std::array<int, 8> nb;
    bool keep = p_.keep_dead_ends && !dead_[start_] && !dead_[goal_];
    for (int end : {start_, goal_}) {
      if (!keep) break;
      const int n = grid_.neighbours(end, nb);
      bool open = n == 0;
      for (int k = 0; k < n; ++k) open = open || !dead_[nb[k]];
      keep = open;
    }
    if (!keep) std::fill(dead_.begin(), dead_.end(), 0);
  }

  // Steps 3-5 for one ant.
  void moveAnt(int a) {
    const int at = paths_[a].back();
    std::array<int, 8> nb;
    const int n_all = grid_.neighbours(at, nb);
    int w[8], z[8];
    int nw = 0, nz = 0;
    for (int k = 0; k < n_all; ++k) {
      if (dead_[nb[k]]) continue;
      w[nw++] = nb[k];
      if (tabu_[nb[k]] == 0) z[nz++] = nb[k];
    }
    int next = -1;
    if (nz >= 1) {
      // Case 1: greedy, the unexplored neighbour nearest to the target (ties at random).
      double best = std::numeric_limits<double>::infinity();
      int ties[8], nt = 0;
      for (int k = 0; k < nz; ++k) {
        const double d = grid_.distance(z[k], target(a));
        if (d < best - 1e-12) {
          best = d;
          nt = 0;
        }
        if (d < best + 1e-12) ties[nt++] = z[k];
      }
      next = ties[nt == 1 ? 0 : pick(nt)];
    } else if (nw > 1) {
      next = w[pick(nw)];  // case 2: all explored, diversify at random
    } else if (nw == 1) {
      dead_[at] = 1;  // case 3: dead end; mark it and back out
      ++dead_marks_;
      next = w[0];
    } else {
      return;  // boxed in by obstacles and marks: the ant waits
    }
    walked_[a].push_back(walked_[a].back() + grid_.stepLength(at, next));
    paths_[a].push_back(next);
    if (tabu_[next] == 0) tabu_[next] = tabuCode(a);
    ++moves_;
  }

  // Index of cell c in ant j's path (first visit), or -1.
  int indexIn(int j, int c) const {
    const auto& path = paths_[j];
    const auto it = std::find(path.begin(), path.end(), c);
    return it == path.end() ? -1 : static_cast<int>(it - path.begin());
  }

  // Step 6: looks for meetings (sets met_); returns true if one gave a path shorter than the best
  // so far.
  // Deviation from the seed (for speed): an ant joins paths when it comes into contact with the
  // other group's trail, not again on every later step while it stays in contact (it then walks
  // through explored territory). On the seed's scenes this gave the same lengths 3-5x faster.
  bool checkMeetings() {
    bool improved = false;
    met_ = false;
    for (int a = 0; a < 2 * m_; ++a) {
      int owner = -1, q = -1;
      const bool met = bestMeeting(a, owner, q);
      const bool fresh = met && !in_contact_[a];
      in_contact_[a] = met;
      if (!fresh) continue;
      ++meetings_;
      met_ = true;
      improved = join(a, paths_[a].back(), owner, q) || improved;
    }
    return improved;
  }

  // Among the cells of ant a's 3x3 neighbourhood (its own cell included) that lie on an
  // opposite-group ant's path, the one giving the shortest unprocessed joined path; only that one
  // is joined and processed (one meeting per ant and step keeps the step cost at O(path)).
  bool bestMeeting(int a, int& owner, int& q) const {
    const int p = paths_[a].back();
    const int px = grid_.x(p), py = grid_.y(p);
    double best = std::numeric_limits<double>::infinity();
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const int cx = px + dx, cy = py + dy;
        if (cx < 0 || cy < 0 || cx >= grid_.nx() || cy >= grid_.ny()) continue;
        const int c = grid_.index(cx, cy);
        int j = -1, k = -1;
        if ((c != p && !grid_.adjacent(p, c)) || !findOwner(a, c, j, k)) continue;
        const double raw = walked_[j][k] + (c == p ? 0.0 : grid_.stepLength(p, c));
        if (raw < best) {
          best = raw;
          owner = j;
          q = k;
        }
      }
    return owner >= 0;
  }

  // Which opposite-group ant's path holds c (and where), by the tabu table version's means.
  bool findOwner(int a, int c, int& owner, int& q) const {
    const int other_first = group(a) == 0 ? m_ : 0;
    const unsigned char t = tabu_[c];
    if (p_.tabu_version == 3) {
      if (t == 0 || (t > 128) == (group(a) == 1)) return false;
      owner = t > 128 ? m_ + (t - 129) : t - 1;
      q = indexIn(owner, c);
      return q >= 0;
    }
    if (p_.tabu_version == 2 && t != 2 - group(a)) return false;
    if (p_.tabu_version == 1 && t == 0) return false;
    // v1/v2: search the other group's paths blindly.
    for (int j = other_first; j < other_first + m_; ++j) {
      q = indexIn(j, c);
      if (q >= 0) {
        owner = j;
        return true;
      }
    }
    return false;
  }

  // Joins ant a's path (ending at p) with ant j's path up to its q-th cell c.
  bool join(int a, int p, int j, int q) {
    const auto& own = paths_[a];
    const auto& other = paths_[j];
    const bool same_cell = other[q] == p;
    std::vector<int> joined;
    joined.reserve(own.size() + q + 1);
    if (group(a) == 0) {
      joined = own;
      for (int i = same_cell ? q - 1 : q; i >= 0; --i) joined.push_back(other[i]);
    } else {
      joined.assign(other.begin(), other.begin() + q + 1);
      for (int i = static_cast<int>(own.size()) - (same_cell ? 2 : 1); i >= 0; --i)
        joined.push_back(own[i]);
    }
    if (p_.post_processing) {
      processing_.removeCycles(joined);
      processing_.smoothLightly(joined);
      if (p_.smoothing_range > 1) {
        processing_.smoothWide(joined, p_.smoothing_range);
        processing_.removeCycles(joined);  // a shortcut may cross a later part of the path
      }
    }
    const double length = grid_.pathLength(joined);
    if (length < best_length_ - 1e-9) {
      best_length_ = length;
      best_.swap(joined);
      return true;
    }
    return false;
  }

  const MsacParams& p_;
  const AntGridView& grid_;
  const int start_, goal_, m_;
  std::mt19937_64 rng_;
  std::vector<unsigned char> tabu_, dead_;
  AntPathProcessing processing_;
  std::vector<std::vector<int>> paths_;  // ants 0..m-1 from the start, m..2m-1 from the goal
  std::vector<std::vector<double>> walked_;
  std::vector<bool> in_contact_;  // length of each path up to each of its cells
  std::vector<int> best_;
  double best_length_ = 0.0, lower_bound_ = 0.0;
  long long moves_ = 0, meetings_ = 0, dead_marks_ = 0;
  bool met_ = false;  // a fresh meeting in the last step
};

}  // namespace

GridPlanResult Msac::solveGrid(const GridQuery& query, const StopToken& stop) {
  const StopToken deadline(query.time_limit_s, stop);
  GridPlanResult result;
  if (p_.ants < 1 || p_.ants > 127 || p_.iterations < 1 || p_.tabu_version < 1 ||
      p_.tabu_version > 3) {
    result.message =
        "MSAC needs 1..127 ants per group (the uint8 tabu table), MAX >= 1 and "
        "tabu_version 1..3";
    result.status = PlannerStatus::InvalidProblem;
    return result;
  }
  const std::optional<AntGridView> ant_grid =
      antGridForQuery(query, p_.conditional_diagonal, result);
  if (!ant_grid) return result;  // rejected, or start == goal
  const AntGridView& grid = *ant_grid;
  const int start = grid.index(query.start), goal = grid.index(query.goal);
  const int n = std::max(grid.nx(), grid.ny());
  const int s_max = p_.s_max > 0 ? p_.s_max : std::max(1, n * n / 2);
  MsacSearch search(p_, grid, start, goal, query.seed);
  const std::vector<int> best = search.run(deadline, s_max, result);
  result.success = !best.empty();
  result.status = searchStatus(result.success, deadline, PlannerStatus::LimitReached);
  if (result.success) {
    result.cells = grid.toCells(best);
    result.length = grid.pathLength(best);
  } else {
    result.message = deadline.expired() ? "time limit reached before the ant groups met"
                                        : "the ant groups did not meet within MAX iterations of "
                                          "S_max steps (goal unreachable or S_max too small)";
  }
  result.time_ms = deadline.elapsedMs();
  return result;
}

}  // namespace cosim
