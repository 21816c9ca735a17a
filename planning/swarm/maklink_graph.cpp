#include "planning/swarm/maklink_graph.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>

namespace cosim {

namespace {

struct Candidate {
  Eigen::Vector2d a, b;
  int va, vb;  // vertex ids of the ends (wall points get their own ids)
  double length;
};

// One end of the lines at a vertex: the directions that bound the free angle there (obstacle
// edges or walls) plus the kept lines.
struct Ray {
  double angle;
  int line;  // -1 for an obstacle edge or a wall
};

}  // namespace

MaklinkGraph::MaklinkGraph(std::vector<ConvexPolygon> obstacles, const Eigen::Vector2d& bounds_min,
                           const Eigen::Vector2d& bounds_max, const StopToken* deadline)
    : obstacles_(std::move(obstacles)), lo_(bounds_min), hi_(bounds_max) {
  auto outOfTime = [&] {
    if (deadline && deadline->expired()) complete_ = false;
    return !complete_;
  };
  // Obstacle vertices that lie in free space (not inside another obstacle, inside the walls).
  struct Vertex {
    Eigen::Vector2d p;
    int polygon, index;
  };
  std::vector<Vertex> vertices;
  for (int o = 0; o < static_cast<int>(obstacles_.size()); ++o)
    for (int i = 0; i < static_cast<int>(obstacles_[o].vertices.size()); ++i) {
      const Eigen::Vector2d& p = obstacles_[o].vertices[i];
      if (pointFree(p)) vertices.push_back({p, o, i});
    }
  const int nv = static_cast<int>(vertices.size());

  // 1. Candidate lines: vertex-vertex (not an edge of one obstacle) and vertex-wall.
  std::vector<Candidate> candidates;
  for (int i = 0; i < nv; ++i) {
    if (outOfTime()) return;
    for (int j = i + 1; j < nv; ++j) {
      const Vertex &u = vertices[i], &w = vertices[j];
      if (u.polygon == w.polygon) {
        const int n = static_cast<int>(obstacles_[u.polygon].vertices.size());
        if ((u.index + 1) % n == w.index || (w.index + 1) % n == u.index) continue;
      }
      if (segmentFree(u.p, w.p)) candidates.push_back({u.p, w.p, i, j, (u.p - w.p).norm()});
    }
  }
  int next_id = nv;
  for (int i = 0; i < nv; ++i) {
    const Eigen::Vector2d p = vertices[i].p;
    const Eigen::Vector2d feet[4] = {
        {lo_.x(), p.y()}, {hi_.x(), p.y()}, {p.x(), lo_.y()}, {p.x(), hi_.y()}};
    for (const Eigen::Vector2d& f : feet)
      if ((f - p).norm() > 1e-9 && segmentFree(p, f))
        candidates.push_back({p, f, i, next_id++, (f - p).norm()});
  }
  std::stable_sort(candidates.begin(), candidates.end(),
                   [](const Candidate& x, const Candidate& y) { return x.length < y.length; });

  // 2a. Shortest first, never crossing a kept line.
  std::vector<Candidate> kept;
  for (std::size_t n = 0; n < candidates.size(); ++n) {
    if ((n & 255) == 0 && outOfTime()) return;
    const Candidate& c = candidates[n];
    bool crosses = false;
    for (const Candidate& k : kept)
      if (segmentsCrossProperly(c.a, c.b, k.a, k.b)) {
        crosses = true;
        break;
      }
    if (!crosses) kept.push_back(c);
  }

  // 2b. Remove lines (longest first) while the free angles at both ends stay <= 180 degrees.
  std::vector<std::vector<Ray>> rays(next_id);
  for (int i = 0; i < nv; ++i) {
    const ConvexPolygon& poly = obstacles_[vertices[i].polygon];
    const int n = static_cast<int>(poly.vertices.size()), k = vertices[i].index;
    for (const Eigen::Vector2d& q : {poly.vertices[(k + 1) % n], poly.vertices[(k + n - 1) % n]}) {
      const Eigen::Vector2d d = q - vertices[i].p;
      rays[i].push_back({std::atan2(d.y(), d.x()), -1});
    }
  }
  std::vector<bool> alive(kept.size(), true);
  for (int l = 0; l < static_cast<int>(kept.size()); ++l) {
    const Candidate& c = kept[l];
    const Eigen::Vector2d d = c.b - c.a;
    rays[c.va].push_back({std::atan2(d.y(), d.x()), l});
    rays[c.vb].push_back({std::atan2(-d.y(), -d.x()), l});
    if (c.vb >= nv) {  // a wall point: the wall runs both ways, perpendicular to the line
      const double a = std::atan2(-d.y(), -d.x());
      rays[c.vb].push_back({a + M_PI / 2, -1});
      rays[c.vb].push_back({a - M_PI / 2, -1});
    }
  }
  // The free angle that the removal of line l would leave at vertex v.
  auto mergedAngle = [&](int v, int l) {
    double at = 0.0;
    for (const Ray& r : rays[v])
      if (r.line == l) at = r.angle;
    double before = 2 * M_PI, after = 2 * M_PI;  // nearest other rays clockwise / anticlockwise
    for (const Ray& r : rays[v]) {
      if (r.line == l || (r.line >= 0 && !alive[r.line])) continue;
      const double ccw = std::fmod(r.angle - at + 4 * M_PI, 2 * M_PI);
      if (ccw > 1e-12) after = std::min(after, ccw);
      const double cw = std::fmod(at - r.angle + 4 * M_PI, 2 * M_PI);
      if (cw > 1e-12) before = std::min(before, cw);
    }
    return before + after;
  };
  for (int l = static_cast<int>(kept.size()) - 1; l >= 0; --l) {
    const Candidate& c = kept[l];
    if (mergedAngle(c.va, l) <= M_PI + 1e-9 && mergedAngle(c.vb, l) <= M_PI + 1e-9)
      alive[l] = false;
  }
  for (std::size_t l = 0; l < kept.size(); ++l)
    if (alive[l]) lines_.push_back({kept[l].a, kept[l].b});
}

bool MaklinkGraph::pointFree(const Eigen::Vector2d& p) const {
  if ((p.array() < lo_.array() - 1e-9).any() || (p.array() > hi_.array() + 1e-9).any())
    return false;
  for (const ConvexPolygon& o : obstacles_)
    if (pointInsidePolygon(p, o)) return false;
  return true;
}

bool MaklinkGraph::segmentFree(const Eigen::Vector2d& a, const Eigen::Vector2d& b) const {
  if (!pointFree(a) || !pointFree(b)) return false;  // the walls are convex: ends suffice
  for (const ConvexPolygon& o : obstacles_)
    if (segmentEntersPolygon(a, b, o)) return false;
  return true;
}

bool MaklinkGraph::crossesNoLine(const Eigen::Vector2d& a, const Eigen::Vector2d& b) const {
  for (const MaklinkLine& l : lines_)
    if (segmentsCrossProperly(a, b, l.a, l.b)) return false;
  return true;
}

MaklinkRoute MaklinkGraph::shortestRoute(const Eigen::Vector2d& start,
                                         const Eigen::Vector2d& goal) const {
  // Nodes: 0 = start, 1 = goal, 2 + i = midpoint of line i.
  std::vector<Eigen::Vector2d> node = {start, goal};
  for (const MaklinkLine& l : lines_) node.push_back(l.midpoint());
  const int n = static_cast<int>(node.size());
  auto joined = [&](int i, int j) {
    return segmentFree(node[i], node[j]) && crossesNoLine(node[i], node[j]);
  };
  std::vector<double> dist(n, std::numeric_limits<double>::infinity());
  std::vector<int> parent(n, -1);
  std::vector<bool> done(n, false);
  dist[0] = 0.0;
  // Dense Dijkstra (the graph has a few hundred nodes; edges are tested when first needed).
  for (int iter = 0; iter < n; ++iter) {
    int u = -1;
    for (int i = 0; i < n; ++i)
      if (!done[i] && (u < 0 || dist[i] < dist[u])) u = i;
    if (u < 0 || !std::isfinite(dist[u])) break;
    done[u] = true;
    if (u == 1) break;
    for (int w = 0; w < n; ++w) {
      if (done[w]) continue;
      const double nd = dist[u] + (node[u] - node[w]).norm();
      if (nd < dist[w] && joined(u, w)) {
        dist[w] = nd;
        parent[w] = u;
      }
    }
  }
  MaklinkRoute route;
  if (!std::isfinite(dist[1])) return route;
  route.found = true;
  route.length = dist[1];
  for (int v = parent[1]; v > 0; v = parent[v]) route.lines.push_back(v - 2);
  std::reverse(route.lines.begin(), route.lines.end());
  return route;
}

}  // namespace cosim
