#pragma once
// Nearest-neighbour queries over the nodes of a growing tree or roadmap, through nanoflann's
// dynamic k-d tree (a forest of static k-d trees of sizes 2^i, rebuilt as points are added: the
// logarithmic method of Bentley & Saxe 1980), so insertion stays cheap and queries sub-linear.
// Points get ids 0, 1, 2, ... in the order they are added; removed ids are never reused.
// With linear_scan, queries instead compute the distance to every live point, as seed 003's
// MATLAB planners did (its RRT*FN "limits memory, which speeds up computing the distances of the
// new node to the rest of the nodes"): the same answers (ties go to the lower id), at a cost that
// grows with the number of points, for reproducing that cost structure.
#include <Eigen/Core>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

namespace cosim {

class NearestNeighborIndex {
 public:
  // capacity: the number of points expected (storage is reserved for them; more still works).
  explicit NearestNeighborIndex(std::size_t capacity, bool linear_scan = false);
  ~NearestNeighborIndex();
  NearestNeighborIndex(const NearestNeighborIndex&) = delete;
  NearestNeighborIndex& operator=(const NearestNeighborIndex&) = delete;

  // Adds p and returns its id (the number of points added before it).
  std::uint32_t add(const Eigen::Vector3d& p);
  void remove(std::uint32_t id);
  std::size_t size() const { return live_; }
  const Eigen::Vector3d& point(std::uint32_t id) const { return points_[id]; }

  // Id of the live point nearest to q (the index must not be empty).
  std::uint32_t nearest(const Eigen::Vector3d& q) const;
  // Live points within `radius` of q, as (id, squared distance), sorted by distance then id.
  void withinRadius(const Eigen::Vector3d& q, double radius,
                    std::vector<std::pair<std::uint32_t, double>>& out) const;
  // The k nearest live points (fewer if there are fewer), sorted by distance then id.
  void nearestK(const Eigen::Vector3d& q, std::size_t k,
                std::vector<std::pair<std::uint32_t, double>>& out) const;

  // nanoflann's dataset interface.
  std::size_t kdtree_get_point_count() const { return points_.size(); }
  double kdtree_get_pt(std::size_t id, std::size_t dim) const { return points_[id][dim]; }
  template <class Box>
  bool kdtree_get_bbox(Box&) const {
    return false;
  }

 private:
  struct Tree;
  std::vector<Eigen::Vector3d> points_;
  std::unique_ptr<Tree> tree_;  // null with linear_scan
  std::vector<std::uint8_t> alive_;
  std::size_t live_ = 0;
  mutable std::vector<std::uint32_t> knn_ids_;
  mutable std::vector<double> knn_d2_;
};

}  // namespace cosim
