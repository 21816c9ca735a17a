#pragma once
// The space-time reservations of a quadrotor team's prioritised search on a dense roadmap: the
// timed vertex paths of the agents planned so far, and whether a new agent's move conflicts with
// any of them by their separation ellipsoids (ellipsoid_conflict.h: vertex, edge and swept, all
// one test). Agents rest at their last vertex for ever.
//
// The reserved moves are kept in buckets per step: cubes of side separation + 2 longest moves in
// coordinates scaled by the ellipsoid (x / r, y / r, z / h). Two moves that come closer than the
// separation start less than that far apart, so their buckets touch: a query looks at the 27
// buckets around its start and sees a handful of agents, however large the team.
#include <Eigen/Core>
#include <climits>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "planning/team/separation_ellipsoid.h"

namespace cosim {

class EllipsoidReservations {
 public:
  static constexpr int kForever = INT_MAX;

  // positions[v]: vertex v's point (m) on a lattice of this pitch (m; moves along one axis).
  // Steps run below 65535.
  EllipsoidReservations(const std::vector<Eigen::Vector3d>& positions,
                        const SeparationEllipsoid& ellipsoid, double separation,
                        const Eigen::Vector3d& pitch);

  // path[t]: the agent's vertex at step t (from 0); it stays at path.back() afterwards.
  void reserve(const std::vector<int>& path);
  void clear();

  // Whether moving from `from` (at step t) to `to` (at t + 1; equal: waiting) comes closer than
  // the separation to a reserved agent's move over the same step.
  bool moveConflicts(int from, int to, int t) const;
  // The last step t whose reserved moves conflict with an agent standing at v through it; -1 if
  // none, kForever if a resting agent does.
  int lastConflictStanding(int v) const;
  // From this step on every reserved agent rests.
  int staticFrom() const { return static_from_; }

 private:
  std::uint64_t bucketKey(int v, int dx, int dy, int dz, int t) const;
  bool conflicts(int from, int to, int other_from, int other_to) const;

  const std::vector<Eigen::Vector3d>& positions_;
  SeparationEllipsoid ellipsoid_;
  double separation_;
  std::vector<Eigen::Vector3i> bucket_;  // per vertex
  std::vector<std::vector<int>> paths_;
  // Moves reserved at step t (timed, agent index), and resting agents (t field kRestingStep).
  std::unordered_map<std::uint64_t, std::vector<int>> moving_, resting_;
  int static_from_ = 0;
};

}  // namespace cosim
