#include "planning/sampling/collision_world.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace cosim {

namespace {

constexpr double kNoObstacleDistance = std::numeric_limits<double>::infinity();
// Obstacle boxes are widened by this much when they are binned into grid cells, so a point on a
// cell face is found in the cells on both sides.
constexpr double kBinPadding = 1e-7;
// A segment whose distance to an inflated cylinder is certified only to within this many metres
// is reported as colliding (conservative; see segmentHitsCylinder).
constexpr double kCylinderTolerance = 1e-9;

// Slab test: does the segment a + t (b - a), t in [0, 1], meet the box [lo, hi]?
bool segmentMeetsAabb(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& lo,
                      const Eigen::Vector3d& hi) {
  double t0 = 0.0, t1 = 1.0;
  for (int i = 0; i < 3; ++i) {
    const double d = b[i] - a[i];
    if (std::abs(d) < 1e-300) {
      if (a[i] < lo[i] || a[i] > hi[i]) return false;
      continue;
    }
    double ta = (lo[i] - a[i]) / d, tb = (hi[i] - a[i]) / d;
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
    if (t0 > t1) return false;
  }
  return true;
}

}  // namespace

CollisionWorld::CollisionWorld(const World& world, double inflation, double bounds_clearance,
                               bool planar)
    : bounds_min_(world.bounds_min), bounds_max_(world.bounds_max), inflation_(inflation) {
  // Only the floor is physical: valid points keep `bounds_clearance` above it (3D problems).
  valid_min_ = bounds_min_;
  valid_max_ = bounds_max_;
  if (!planar) valid_min_.z() += bounds_clearance;
  shapes_.reserve(world.obstacles.size());
  for (const Obstacle& o : world.obstacles) {
    Shape s;
    s.type = o.type;
    s.center = o.pos;
    const double yaw = o.yaw_deg * M_PI / 180.0;
    s.cos_yaw = std::cos(yaw);
    s.sin_yaw = std::sin(yaw);
    s.radius = o.radius;
    switch (o.type) {
      case ObstacleType::Box:
        s.half = 0.5 * o.size;
        break;
      case ObstacleType::Cylinder:
        s.half = {o.radius, o.radius, 0.5 * o.height};
        break;
      case ObstacleType::Sphere:
        s.half.setConstant(o.radius);
        break;
    }
    o.boundingBox(inflation, s.aabb_lo, s.aabb_hi);
    shapes_.push_back(s);
  }
  visit_stamp_.assign(shapes_.size(), 0);

  // Broad phase: about one obstacle per cell on average, at most 128 cells along an axis. A flat
  // world (zero extent along an axis) is binned in the remaining axes only.
  const Eigen::Vector3d extent = (bounds_max_ - bounds_min_).cwiseMax(1e-9);
  double measure = 1.0;
  int flat_dims = 0;
  for (int i = 0; i < 3; ++i)
    if (extent[i] > 1e-6) measure *= extent[i], ++flat_dims;
  const double n = static_cast<double>(std::max<std::size_t>(shapes_.size(), 1));
  cell_size_ = flat_dims == 0 ? 1.0 : std::pow(measure / n, 1.0 / flat_dims);
  cell_size_ = std::max(cell_size_, extent.maxCoeff() / 127.5);
  for (int i = 0; i < 3; ++i)
    dims_[i] = std::clamp(static_cast<int>(std::ceil(extent[i] / cell_size_)), 1, 128);

  const std::size_t cells = static_cast<std::size_t>(dims_.prod());
  std::vector<std::uint32_t> counts(cells + 1, 0);
  auto forEachCell = [&](const Shape& s, auto&& visit) {
    const Eigen::Vector3d pad = Eigen::Vector3d::Constant(kBinPadding);
    const Eigen::Vector3d lo = s.aabb_lo - pad, hi = s.aabb_hi + pad;
    // Obstacles outside the bounds are clipped into the border cells: free points never touch
    // them, but distanceToObstacles must still see them.
    const Eigen::Vector3i c0 = cellOf(lo), c1 = cellOf(hi);
    for (int z = c0.z(); z <= c1.z(); ++z)
      for (int y = c0.y(); y <= c1.y(); ++y)
        for (int x = c0.x(); x <= c1.x(); ++x) visit(cellIndex(x, y, z));
  };
  for (const Shape& s : shapes_) forEachCell(s, [&](std::size_t c) { ++counts[c + 1]; });
  for (std::size_t c = 0; c < cells; ++c) counts[c + 1] += counts[c];
  cell_start_ = counts;
  cell_items_.resize(counts[cells]);
  for (std::uint32_t i = 0; i < shapes_.size(); ++i)
    forEachCell(shapes_[i], [&](std::size_t c) { cell_items_[counts[c]++] = i; });
}

bool CollisionWorld::insideBounds(const Eigen::Vector3d& p) const {
  return (p.array() >= valid_min_.array()).all() && (p.array() <= valid_max_.array()).all();
}

Eigen::Vector3i CollisionWorld::cellOf(const Eigen::Vector3d& p) const {
  Eigen::Vector3i c;
  for (int i = 0; i < 3; ++i)
    c[i] = std::clamp(static_cast<int>(std::floor((p[i] - bounds_min_[i]) / cell_size_)), 0,
                      dims_[i] - 1);
  return c;
}

bool CollisionWorld::firstVisit(std::uint32_t i) const {
  if (visit_stamp_[i] == query_id_) return false;
  visit_stamp_[i] = query_id_;
  return true;
}

Eigen::Vector3d CollisionWorld::toLocal(const Shape& s, const Eigen::Vector3d& p) const {
  const Eigen::Vector3d d = p - s.center;
  return {s.cos_yaw * d.x() + s.sin_yaw * d.y(), -s.sin_yaw * d.x() + s.cos_yaw * d.y(), d.z()};
}

double CollisionWorld::signedDistance(const Shape& s, const Eigen::Vector3d& p) const {
  switch (s.type) {
    case ObstacleType::Sphere:
      return (p - s.center).norm() - s.radius;
    case ObstacleType::Box: {
      const Eigen::Vector3d d = toLocal(s, p).cwiseAbs() - s.half;
      return d.cwiseMax(0.0).norm() + std::min(d.maxCoeff(), 0.0);
    }
    case ObstacleType::Cylinder: {
      const Eigen::Vector3d q = p - s.center;
      const double radial = std::hypot(q.x(), q.y()) - s.radius;
      const double axial = std::abs(q.z()) - s.half.z();
      return std::hypot(std::max(radial, 0.0), std::max(axial, 0.0)) +
             std::min(std::max(radial, axial), 0.0);
    }
  }
  return kNoObstacleDistance;
}

bool CollisionWorld::pointFree(const Eigen::Vector3d& p) const {
  if (!insideBounds(p)) return false;
  if (shapes_.empty()) return true;
  const Eigen::Vector3i c = cellOf(p);
  const std::size_t cell = cellIndex(c.x(), c.y(), c.z());
  for (std::uint32_t k = cell_start_[cell]; k < cell_start_[cell + 1]; ++k) {
    const Shape& s = shapes_[cell_items_[k]];
    if ((p.array() < s.aabb_lo.array()).any() || (p.array() > s.aabb_hi.array()).any()) continue;
    if (signedDistance(s, p) <= inflation_) return false;
  }
  return true;
}

// Segment against the box grown by r (a rounded box): in the box frame the squared distance
// from a + t d to the box is sum_i max(0, |a_i + t d_i| - h_i)^2, a quadratic in t between the
// (at most six) values of t where a coordinate crosses a face plane. Its minimum over [0, 1] is
// therefore found exactly by minimising each quadratic piece in closed form.
bool CollisionWorld::segmentHitsBox(const Shape& s, const Eigen::Vector3d& a_world,
                                    const Eigen::Vector3d& b_world) const {
  const Eigen::Vector3d a = toLocal(s, a_world);
  const Eigen::Vector3d d = toLocal(s, b_world) - a;
  const Eigen::Vector3d& h = s.half;
  std::array<double, 8> breaks;
  int nb = 0;
  breaks[nb++] = 0.0;
  for (int i = 0; i < 3; ++i) {
    if (d[i] == 0.0) continue;
    for (double face : {-h[i], h[i]}) {
      const double t = (face - a[i]) / d[i];
      if (t > 0.0 && t < 1.0) breaks[nb++] = t;
    }
  }
  breaks[nb++] = 1.0;
  for (int i = 1; i < nb; ++i)  // insertion sort of at most 8 values
    for (int j = i; j > 0 && breaks[j] < breaks[j - 1]; --j) std::swap(breaks[j], breaks[j - 1]);
  const double r2 = inflation_ * inflation_;
  for (int k = 0; k + 1 < nb; ++k) {
    const double t0 = breaks[k], t1 = breaks[k + 1];
    const double tm = 0.5 * (t0 + t1);
    // Coefficients of A t^2 + B t + C on this piece.
    double A = 0.0, B = 0.0, C = 0.0;
    for (int i = 0; i < 3; ++i) {
      const double v = a[i] + tm * d[i];
      double offset;
      if (v > h[i])
        offset = a[i] - h[i];
      else if (v < -h[i])
        offset = a[i] + h[i];
      else
        continue;
      A += d[i] * d[i];
      B += 2.0 * offset * d[i];
      C += offset * offset;
    }
    double t = t0;
    if (A > 0.0) t = std::clamp(-B / (2.0 * A), t0, t1);
    const double v0 = (A * t0 + B) * t0 + C, v1 = (A * t1 + B) * t1 + C;
    const double vt = (A * t + B) * t + C;
    if (std::min({v0, v1, vt}) <= r2) return true;
  }
  return false;
}

// Segment against the cylinder grown by r. The signed distance to a convex body is a convex
// function of t along the segment and |b - a|-Lipschitz, so a golden-section search either finds
// a point within r (hit) or proves, from the Lipschitz cones over the remaining bracket, that the
// minimum stays above r (miss). If neither is settled when the bracket is below
// kCylinderTolerance metres, the segment grazes the surface and is reported as a hit.
bool CollisionWorld::segmentHitsCylinder(const Shape& s, const Eigen::Vector3d& a,
                                         const Eigen::Vector3d& b) const {
  const Eigen::Vector3d d = b - a;
  const double r = inflation_;
  const double L = d.norm();
  auto f = [&](double t) { return signedDistance(s, a + t * d); };
  double lo = 0.0, hi = 1.0, flo = f(lo), fhi = f(hi);
  if (flo <= r || fhi <= r) return true;
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo);
  double f1 = f(x1), f2 = f(x2);
  for (int it = 0; it < 200; ++it) {
    if (f1 <= r || f2 <= r) return true;
    // The minimum lies in [lo, hi]; by the Lipschitz bound it is at least this.
    if (0.5 * (flo + fhi - L * (hi - lo)) > r) return false;
    if (L * (hi - lo) < kCylinderTolerance) return true;
    if (f1 < f2) {
      hi = x2, fhi = f2;
      x2 = x1, f2 = f1;
      x1 = hi - g * (hi - lo), f1 = f(x1);
    } else {
      lo = x1, flo = f1;
      x1 = x2, f1 = f2;
      x2 = lo + g * (hi - lo), f2 = f(x2);
    }
  }
  return true;
}

bool CollisionWorld::segmentHits(const Shape& s, const Eigen::Vector3d& a,
                                 const Eigen::Vector3d& b) const {
  if (!segmentMeetsAabb(a, b, s.aabb_lo, s.aabb_hi)) return false;
  switch (s.type) {
    case ObstacleType::Sphere: {
      // Closest point of the segment to the centre, in closed form.
      const Eigen::Vector3d d = b - a;
      const double dd = d.squaredNorm();
      const double t = dd > 0.0 ? std::clamp((s.center - a).dot(d) / dd, 0.0, 1.0) : 0.0;
      const double reach = s.radius + inflation_;
      return (a + t * d - s.center).squaredNorm() <= reach * reach;
    }
    case ObstacleType::Box:
      return segmentHitsBox(s, a, b);
    case ObstacleType::Cylinder:
      return segmentHitsCylinder(s, a, b);
  }
  return true;
}

bool CollisionWorld::cellFreeOfSegment(std::size_t cell, const Eigen::Vector3d& a,
                                       const Eigen::Vector3d& b) const {
  for (std::uint32_t k = cell_start_[cell]; k < cell_start_[cell + 1]; ++k) {
    const std::uint32_t i = cell_items_[k];
    if (firstVisit(i) && segmentHits(shapes_[i], a, b)) return false;
  }
  return true;
}

bool CollisionWorld::segmentFree(const Eigen::Vector3d& a, const Eigen::Vector3d& b) const {
  if (!insideBounds(a) || !insideBounds(b)) return false;
  if (shapes_.empty()) return true;
  if (++query_id_ == 0) {  // the stamp wrapped around: forget all visits
    std::fill(visit_stamp_.begin(), visit_stamp_.end(), 0);
    query_id_ = 1;
  }
  // Walk the cells the segment passes through (Amanatides & Woo 1987, "A fast voxel traversal
  // algorithm for ray tracing").
  const Eigen::Vector3d d = b - a;
  Eigen::Vector3i c = cellOf(a);
  Eigen::Vector3i step;
  Eigen::Vector3d t_max, t_delta;
  for (int i = 0; i < 3; ++i) {
    if (d[i] > 0.0) {
      step[i] = 1;
      t_max[i] = (bounds_min_[i] + (c[i] + 1) * cell_size_ - a[i]) / d[i];
      t_delta[i] = cell_size_ / d[i];
    } else if (d[i] < 0.0) {
      step[i] = -1;
      t_max[i] = (bounds_min_[i] + c[i] * cell_size_ - a[i]) / d[i];
      t_delta[i] = -cell_size_ / d[i];
    } else {
      step[i] = 0;
      t_max[i] = kNoObstacleDistance;
      t_delta[i] = kNoObstacleDistance;
    }
  }
  const int max_cells = dims_.sum() + 3;
  for (int visited = 0; visited < max_cells; ++visited) {
    if (!cellFreeOfSegment(cellIndex(c.x(), c.y(), c.z()), a, b)) return false;
    int axis = 0;
    if (t_max[1] < t_max[axis]) axis = 1;
    if (t_max[2] < t_max[axis]) axis = 2;
    if (t_max[axis] > 1.0) break;
    c[axis] += step[axis];
    if (c[axis] < 0 || c[axis] >= dims_[axis]) break;
    t_max[axis] += t_delta[axis];
  }
  return true;
}

double CollisionWorld::distanceToObstacles(const Eigen::Vector3d& p) const {
  double best = kNoObstacleDistance;
  if (!insideBounds(p)) {
    for (const Shape& s : shapes_) best = std::min(best, signedDistance(s, p));
    return best;
  }
  if (++query_id_ == 0) {
    std::fill(visit_stamp_.begin(), visit_stamp_.end(), 0);
    query_id_ = 1;
  }
  // Search shells of cells of growing Chebyshev radius k around p's cell. An obstacle's surface
  // lies in its bounding box, which is binned into every cell it covers (clipped to the grid),
  // so an obstacle first met in shell k + 1 or later is at least k cells away from p.
  const Eigen::Vector3i c = cellOf(p);
  const int max_k = dims_.maxCoeff();
  for (int k = 0; k <= max_k; ++k) {
    if (best <= (k - 1) * cell_size_) break;
    for (int z = c.z() - k; z <= c.z() + k; ++z) {
      if (z < 0 || z >= dims_.z()) continue;
      for (int y = c.y() - k; y <= c.y() + k; ++y) {
        if (y < 0 || y >= dims_.y()) continue;
        for (int x = c.x() - k; x <= c.x() + k; ++x) {
          if (x < 0 || x >= dims_.x()) continue;
          const int shell =
              std::max({std::abs(x - c.x()), std::abs(y - c.y()), std::abs(z - c.z())});
          if (shell != k) continue;
          const std::size_t cell = cellIndex(x, y, z);
          for (std::uint32_t j = cell_start_[cell]; j < cell_start_[cell + 1]; ++j) {
            const std::uint32_t i = cell_items_[j];
            if (firstVisit(i)) best = std::min(best, signedDistance(shapes_[i], p));
          }
        }
      }
    }
  }
  return best;
}

}  // namespace cosim
