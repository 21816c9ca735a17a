#include "planning/sampling/nearest_neighbor_index.h"

#include <algorithm>
#include <limits>
// nanoflann 1.4.3 leaves a bounding box uninitialised until it is built; GCC 12 warns about it
// when inlining, though it is always written before use.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <nanoflann.hpp>
#pragma GCC diagnostic pop

namespace cosim {

using KdForest = nanoflann::KDTreeSingleIndexDynamicAdaptor<
    nanoflann::L2_Simple_Adaptor<double, NearestNeighborIndex, double, std::uint32_t>,
    NearestNeighborIndex, 3, std::uint32_t>;

struct NearestNeighborIndex::Tree {
  KdForest forest;
  // The forest is sized for every id a uint32 can hold (32 trees; empty ones cost a branch per
  // query): nanoflann's dynamic index must never receive more points than this bound.
  explicit Tree(const NearestNeighborIndex& data)
      : forest(3, data, nanoflann::KDTreeSingleIndexAdaptorParams(10 /* leaf size */),
               std::numeric_limits<std::uint32_t>::max()) {}
};

namespace {
// Sorted by distance, ties by id: the order never depends on the forest's layout.
void sortByDistance(std::vector<std::pair<std::uint32_t, double>>& v) {
  std::sort(v.begin(), v.end(), [](const auto& x, const auto& y) {
    return x.second != y.second ? x.second < y.second : x.first < y.first;
  });
}
}  // namespace

NearestNeighborIndex::NearestNeighborIndex(std::size_t capacity, bool linear_scan) {
  points_.reserve(capacity);
  alive_.reserve(capacity);
  if (!linear_scan) tree_ = std::make_unique<Tree>(*this);
}

NearestNeighborIndex::~NearestNeighborIndex() = default;

std::uint32_t NearestNeighborIndex::add(const Eigen::Vector3d& p) {
  const auto id = static_cast<std::uint32_t>(points_.size());
  points_.push_back(p);
  alive_.push_back(1);
  if (tree_) tree_->forest.addPoints(id, id);
  ++live_;
  return id;
}

void NearestNeighborIndex::remove(std::uint32_t id) {
  if (tree_) tree_->forest.removePoint(id);
  alive_[id] = 0;
  --live_;
}

std::uint32_t NearestNeighborIndex::nearest(const Eigen::Vector3d& q) const {
  if (!tree_) {
    std::uint32_t best = 0;
    double best_d2 = std::numeric_limits<double>::infinity();
    for (std::uint32_t i = 0; i < points_.size(); ++i) {
      if (!alive_[i]) continue;
      const double d2 = (points_[i] - q).squaredNorm();
      if (d2 < best_d2) best_d2 = d2, best = i;
    }
    return best;
  }
  std::uint32_t id = 0;
  double d2 = 0.0;
  nanoflann::KNNResultSet<double, std::uint32_t> result(1);
  result.init(&id, &d2);
  tree_->forest.findNeighbors(result, q.data(), nanoflann::SearchParams());
  return id;
}

void NearestNeighborIndex::withinRadius(const Eigen::Vector3d& q, double radius,
                                        std::vector<std::pair<std::uint32_t, double>>& out) const {
  if (!tree_) {
    out.clear();
    const double r2 = radius * radius;
    for (std::uint32_t i = 0; i < points_.size(); ++i) {
      if (!alive_[i]) continue;
      const double d2 = (points_[i] - q).squaredNorm();
      if (d2 <= r2) out.emplace_back(i, d2);
    }
    sortByDistance(out);
    return;
  }
  nanoflann::RadiusResultSet<double, std::uint32_t> result(radius * radius, out);
  tree_->forest.findNeighbors(result, q.data(), nanoflann::SearchParams());
  sortByDistance(out);
}

void NearestNeighborIndex::nearestK(const Eigen::Vector3d& q, std::size_t k,
                                    std::vector<std::pair<std::uint32_t, double>>& out) const {
  out.clear();
  k = std::min(k, live_);
  if (k == 0) return;
  if (!tree_) {
    for (std::uint32_t i = 0; i < points_.size(); ++i)
      if (alive_[i]) out.emplace_back(i, (points_[i] - q).squaredNorm());
    sortByDistance(out);
    out.resize(k);
    return;
  }
  knn_ids_.resize(k);
  knn_d2_.resize(k);
  nanoflann::KNNResultSet<double, std::uint32_t> result(k);
  result.init(knn_ids_.data(), knn_d2_.data());
  tree_->forest.findNeighbors(result, q.data(), nanoflann::SearchParams());
  for (std::size_t i = 0; i < result.size(); ++i) out.emplace_back(knn_ids_[i], knn_d2_[i]);
  sortByDistance(out);
}

}  // namespace cosim
