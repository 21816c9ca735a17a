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

// An obstacle vertex that lies in free space (not inside another obstacle, inside the walls).
struct Vertex {
  Eigen::Vector2d p;
  int polygon, index;
};

bool expired(const StopToken* deadline) {
  return deadline && deadline->expired();
}

std::vector<Vertex> freeVertices(const MaklinkGraph& graph) {
  std::vector<Vertex> vertices;
  const std::vector<ConvexPolygon>& obstacles = graph.obstacles();
  for (int o = 0; o < static_cast<int>(obstacles.size()); ++o)
    for (int i = 0; i < static_cast<int>(obstacles[o].vertices.size()); ++i) {
      const Eigen::Vector2d& p = obstacles[o].vertices[i];
      if (graph.pointFree(p)) vertices.push_back({p, o, i});
    }
  return vertices;
}

// 1. Candidate lines: vertex-vertex (not an edge of one obstacle) and vertex-wall, shortest
// first. Wall points get the ids from vertices.size() up; ids: one past the last. False if the
// deadline expired.
bool candidateLines(const MaklinkGraph& graph, const std::vector<Vertex>& vertices,
                    const Eigen::Vector2d& lo, const Eigen::Vector2d& hi, const StopToken* deadline,
                    std::vector<Candidate>& candidates, int& ids) {
  const int nv = static_cast<int>(vertices.size());
  for (int i = 0; i < nv; ++i) {
    if (expired(deadline)) return false;
    for (int j = i + 1; j < nv; ++j) {
      const Vertex &u = vertices[i], &w = vertices[j];
      if (u.polygon == w.polygon) {
        const int n = static_cast<int>(graph.obstacles()[u.polygon].vertices.size());
        if ((u.index + 1) % n == w.index || (w.index + 1) % n == u.index) continue;
      }
      if (graph.segmentFree(u.p, w.p)) candidates.push_back({u.p, w.p, i, j, (u.p - w.p).norm()});
    }
  }
  ids = nv;
  for (int i = 0; i < nv; ++i) {
    const Eigen::Vector2d p = vertices[i].p;
    const Eigen::Vector2d feet[4] = {
        {lo.x(), p.y()}, {hi.x(), p.y()}, {p.x(), lo.y()}, {p.x(), hi.y()}};
    for (const Eigen::Vector2d& f : feet)
      if ((f - p).norm() > 1e-9 && graph.segmentFree(p, f))
        candidates.push_back({p, f, i, ids++, (f - p).norm()});
  }
  std::stable_sort(candidates.begin(), candidates.end(),
                   [](const Candidate& x, const Candidate& y) { return x.length < y.length; });
  return true;
}

// 2a. Shortest first, never crossing a kept line. False if the deadline expired.
bool keepNonCrossing(const std::vector<Candidate>& candidates, const StopToken* deadline,
                     std::vector<Candidate>& kept) {
  for (std::size_t n = 0; n < candidates.size(); ++n) {
    if ((n & 255) == 0 && expired(deadline)) return false;
    const Candidate& c = candidates[n];
    bool crosses = false;
    for (const Candidate& k : kept)
      if (segmentsCrossProperly(c.a, c.b, k.a, k.b)) {
        crosses = true;
        break;
      }
    if (!crosses) kept.push_back(c);
  }
  return true;
}

// The rays at every vertex id: the two obstacle edges at an obstacle vertex, the wall both ways
// at a wall point, and the kept lines at both their ends.
std::vector<std::vector<Ray>> raysAtVertices(const std::vector<ConvexPolygon>& obstacles,
                                             const std::vector<Vertex>& vertices,
                                             const std::vector<Candidate>& kept, int ids) {
  const int nv = static_cast<int>(vertices.size());
  std::vector<std::vector<Ray>> rays(ids);
  for (int i = 0; i < nv; ++i) {
    const ConvexPolygon& poly = obstacles[vertices[i].polygon];
    const int n = static_cast<int>(poly.vertices.size()), k = vertices[i].index;
    for (const Eigen::Vector2d& q : {poly.vertices[(k + 1) % n], poly.vertices[(k + n - 1) % n]}) {
      const Eigen::Vector2d d = q - vertices[i].p;
      rays[i].push_back({std::atan2(d.y(), d.x()), -1});
    }
  }
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
  return rays;
}

// 2b. Remove lines (longest first) while the free angles at both ends stay <= 180 degrees.
// Returns which of the kept lines remain.
std::vector<bool> pruneRedundant(const std::vector<std::vector<Ray>>& rays,
                                 const std::vector<Candidate>& kept) {
  std::vector<bool> alive(kept.size(), true);
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
  return alive;
}

}  // namespace

MaklinkGraph::MaklinkGraph(std::vector<ConvexPolygon> obstacles, const Eigen::Vector2d& bounds_min,
                           const Eigen::Vector2d& bounds_max, const StopToken* deadline)
    : obstacles_(std::move(obstacles)), lo_(bounds_min), hi_(bounds_max) {
  const std::vector<Vertex> vertices = freeVertices(*this);
  std::vector<Candidate> candidates, kept;
  int ids = 0;
  if (!candidateLines(*this, vertices, lo_, hi_, deadline, candidates, ids) ||
      !keepNonCrossing(candidates, deadline, kept)) {
    complete_ = false;
    return;
  }
  const std::vector<bool> alive =
      pruneRedundant(raysAtVertices(obstacles_, vertices, kept, ids), kept);
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
