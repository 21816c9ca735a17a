#include "planning/team/ellipsoid_reservations.h"

#include <algorithm>
#include <cmath>

#include "planning/team/ellipsoid_conflict.h"

namespace cosim {

namespace {

constexpr int kRestingStep = 0xffff;  // the bucket key's step field for resting agents

}  // namespace

EllipsoidReservations::EllipsoidReservations(const std::vector<Eigen::Vector3d>& positions,
                                             const SeparationEllipsoid& ellipsoid,
                                             double separation, const Eigen::Vector3d& pitch)
    : positions_(positions), ellipsoid_(ellipsoid), separation_(separation) {
  const Eigen::Vector3d scale(1.0 / ellipsoid.radius, 1.0 / ellipsoid.radius,
                              1.0 / ellipsoid.height);
  Eigen::Vector3d low = Eigen::Vector3d::Constant(1e300);
  for (const auto& p : positions) low = low.cwiseMin(p);
  const double longest = scale.cwiseProduct(pitch).maxCoeff();  // one lattice step, scaled
  const double side = separation + 2.0 * longest;
  bucket_.reserve(positions.size());
  for (const auto& p : positions) {
    const Eigen::Vector3d q = scale.cwiseProduct(p - low) / side;
    bucket_.emplace_back(static_cast<int>(q.x()), static_cast<int>(q.y()), static_cast<int>(q.z()));
  }
}

std::uint64_t EllipsoidReservations::bucketKey(int v, int dx, int dy, int dz, int t) const {
  const Eigen::Vector3i& b = bucket_[v];
  // One bucket beyond either edge wraps to 0xffff, which no real bucket has: no false match.
  const auto field = [](int x) { return static_cast<std::uint64_t>(x & 0xffff); };
  return field(t) << 48 | field(b.x() + dx) << 32 | field(b.y() + dy) << 16 | field(b.z() + dz);
}

void EllipsoidReservations::reserve(const std::vector<int>& path) {
  const int agent = static_cast<int>(paths_.size());
  paths_.push_back(path);
  const int last = static_cast<int>(path.size()) - 1;
  for (int t = 0; t < last; ++t) moving_[bucketKey(path[t], 0, 0, 0, t)].push_back(agent);
  resting_[bucketKey(path[last], 0, 0, 0, kRestingStep)].push_back(agent);
  static_from_ = std::max(static_from_, last);
}

void EllipsoidReservations::clear() {
  paths_.clear();
  moving_.clear();
  resting_.clear();
  static_from_ = 0;
}

bool EllipsoidReservations::conflicts(int from, int to, int other_from, int other_to) const {
  return sweptEllipsoidDistance(ellipsoid_, positions_[from], positions_[to],
                                positions_[other_from], positions_[other_to]) < separation_;
}

bool EllipsoidReservations::moveConflicts(int from, int to, int t) const {
  for (int dz = -1; dz <= 1; ++dz)
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        if (t < kRestingStep) {
          const auto m = moving_.find(bucketKey(from, dx, dy, dz, t));
          if (m != moving_.end())
            for (const int b : m->second)
              if (conflicts(from, to, paths_[b][t], paths_[b][t + 1])) return true;
        }
        const auto r = resting_.find(bucketKey(from, dx, dy, dz, kRestingStep));
        if (r == resting_.end()) continue;
        for (const int b : r->second) {
          const auto& p = paths_[b];
          if (t >= static_cast<int>(p.size()) - 1 && conflicts(from, to, p.back(), p.back()))
            return true;
        }
      }
  return false;
}

int EllipsoidReservations::lastConflictStanding(int v) const {
  int last = -1;
  for (const auto& p : paths_) {
    if (conflicts(v, v, p.back(), p.back())) return kForever;
    for (int t = static_cast<int>(p.size()) - 2; t > last; --t)
      if (conflicts(v, v, p[t], p[t + 1])) {
        last = t;
        break;
      }
  }
  return last;
}

}  // namespace cosim
