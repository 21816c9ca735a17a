#include "planning/team/dense_roadmap.h"

#include <cmath>
#include <optional>
#include <string>

#include "core/input_error.h"
#include "planning/team/ellipsoid_conflict.h"

namespace cosim {

namespace {

constexpr int kFinestRefinement = 4;
// Neighbouring vertices of the k = 1 lattice are exactly one separation apart: a hair more
// pitch keeps round-off from making that a conflict.
constexpr double kRoadmapPitchRoundOff = 1.0 + 1e-6;

// Starts and goals within this of one height are a planar team (m).
constexpr double kSameHeight = 1e-6;

struct Failure {
  std::string place, problem;
};

std::string key(std::size_t i, const std::string& what) {
  return "vehicles[" + std::to_string(i) + "]." + what;
}

// Points closer than the separation cannot be held by any roadmap.
void requireApart(const std::vector<Eigen::Vector3d>& points, const std::string& what,
                  const SeparationEllipsoid& e, double separation) {
  for (std::size_t j = 1; j < points.size(); ++j)
    for (std::size_t i = 0; i < j; ++i) {
      const double d = e.distance(points[i], points[j]);
      if (d < separation)
        throw InputError("", key(j, what),
                         "is " + std::to_string(d) + " separation ellipsoids from " + key(i, what) +
                             ", less than the " + std::to_string(separation) +
                             " the team's plan keeps (planner.min_separation, grown by the "
                             "controller's tracking error); move them further apart");
    }
}

// Each point's vertex, or the first failure: a point in a blocked cell, or a pair whose move
// between point and vertex (flown by all at once) comes closer than the separation.
bool snap(const DenseRoadmap& r, const std::vector<Eigen::Vector3d>& points,
          const std::string& what, const SeparationEllipsoid& e, double separation,
          std::vector<int>& vertices, Failure& failure) {
  vertices.clear();
  for (std::size_t i = 0; i < points.size(); ++i) {
    const int v = r.graph.vertexOf(r.grid.cellOf(points[i]));
    if (v == MapfGraph::kNoVertex) {
      failure = {key(i, what),
                 "lies in a blocked cell of the team's roadmap (too close to an obstacle or the "
                 "bounds for the vehicle's radius plus planner.margin), or outside it"};
      return false;
    }
    vertices.push_back(v);
  }
  for (std::size_t j = 1; j < points.size(); ++j)
    for (std::size_t i = 0; i < j; ++i)
      if (sweptEllipsoidDistance(e, points[i], r.positions[vertices[i]], points[j],
                                 r.positions[vertices[j]]) < separation) {
        failure = {key(j, what), "and " + key(i, what) +
                                     " land on roadmap vertices closer than the separation even "
                                     "on the finest roadmap; move them further apart"};
        return false;
      }
  return true;
}

// The layer of the lattice holding every start and goal, when they all lie at one height.
std::optional<int> commonLayer(const TeamGrid& grid, const std::vector<Eigen::Vector3d>& starts,
                               const std::vector<Eigen::Vector3d>& goals) {
  if (starts.empty()) return std::nullopt;
  const double z = starts.front().z();
  for (const auto* points : {&starts, &goals})
    for (const auto& p : *points)
      if (std::abs(p.z() - z) > kSameHeight) return std::nullopt;
  return grid.cellOf(starts.front()).z;
}

bool tryLattice(const World& world, const std::vector<Eigen::Vector3d>& starts,
                const std::vector<Eigen::Vector3d>& goals, const SeparationEllipsoid& e,
                double separation, double inflation, int k, const Eigen::Vector3d* anchor,
                bool allow_planar, DenseRoadmap& out, Failure& failure) {
  const Eigen::Vector3d pitch =
      separation * kRoadmapPitchRoundOff / k * Eigen::Vector3d(e.radius, e.radius, e.height);
  DenseRoadmap r{anchor ? TeamGrid::over(world, pitch, inflation, *anchor)
                        : TeamGrid::over(world, pitch, inflation),
                 MapfGraph(),
                 {},
                 {},
                 {},
                 k};
  OccupancyGrid cells = r.grid.occupancy();
  const auto layer = allow_planar ? commonLayer(r.grid, starts, goals) : std::nullopt;
  r.planar = layer.has_value();
  if (layer)
    for (int z = 0; z < cells.nz(); ++z)
      for (int y = 0; z != *layer && y < cells.ny(); ++y)
        for (int x = 0; x < cells.nx(); ++x) cells.setBlocked(x, y, z, true);
  r.graph = MapfGraph::fromGrid(cells, 6);
  r.positions.reserve(r.graph.vertexCount());
  for (int v = 0; v < r.graph.vertexCount(); ++v)
    r.positions.push_back(r.grid.centre(r.graph.cellOf(v)));
  if (!snap(r, starts, "start", e, separation, r.starts, failure) ||
      !snap(r, goals, "goal", e, separation, r.goals, failure))
    return false;
  out = std::move(r);
  return true;
}

}  // namespace

DenseRoadmap denseRoadmap(const World& world, const std::vector<Eigen::Vector3d>& starts,
                          const std::vector<Eigen::Vector3d>& goals,
                          const SeparationEllipsoid& ellipsoid, double separation, double inflation,
                          bool allow_planar) {
  requireApart(starts, "start", ellipsoid, separation);
  requireApart(goals, "goal", ellipsoid, separation);
  DenseRoadmap out;
  Failure failure;
  for (int k = 1; k <= kFinestRefinement; ++k)
    for (const bool anchored : {true, false})
      if (tryLattice(world, starts, goals, ellipsoid, separation, inflation, k,
                     anchored && !starts.empty() ? &starts.front() : nullptr, allow_planar, out,
                     failure))
        return out;
  throw InputError("", failure.place, failure.problem);
}

}  // namespace cosim
