#include "experiments/bench/grid_astar_vs_boost.h"

#include <algorithm>
#include <boost/graph/astar_search.hpp>
#include <boost/graph/compressed_sparse_row_graph.hpp>
#include <cmath>
#include <cstdint>
#include <ctime>
#include <filesystem>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "experiments/bench/thread_cpu_clock.h"
#include "planning/grid/astar.h"
#include "planning/grid/grid_distance.h"
#include "planning/grid/movingai.h"

namespace cosim::bench {
namespace {

// Thread CPU time, not wall time: the machine is shared.
double cpuMs() { return threadCpuMs(); }

struct Query {
  Cell start, goal;
};

// ---- Boost.Graph side: the free cells as vertices, legal moves as weighted edges. ----
struct EdgeWeight {
  double w;
};
using BoostGraph =
    boost::compressed_sparse_row_graph<boost::directedS, boost::no_property, EdgeWeight,
                                       boost::no_property, std::uint32_t, std::uint32_t>;
using Vertex = std::uint32_t;

struct BoostGrid {
  BoostGraph graph;
  std::vector<Cell> cells;           // vertex -> cell
  std::vector<std::int64_t> vertex;  // grid index -> vertex, -1 for blocked cells
};

BoostGrid buildBoostGrid(const OccupancyGrid& grid, const GridMoves& moves) {
  BoostGrid b;
  b.vertex.assign(grid.cellCount(), -1);
  for (std::size_t i = 0; i < grid.cellCount(); ++i) {
    const Cell c = grid.cellAt(i);
    if (grid.free(c)) {
      b.vertex[i] = static_cast<std::int64_t>(b.cells.size());
      b.cells.push_back(c);
    }
  }
  std::vector<std::pair<Vertex, Vertex>> edges;
  std::vector<EdgeWeight> weights;
  const auto steps = gridSteps(moves, grid.is3D());
  for (Vertex v = 0; v < b.cells.size(); ++v)
    for (const GridStep& s : steps)
      if (gridStepAllowed(grid, b.cells[v], s, moves.corner_cutting)) {
        const Cell t{b.cells[v].x + s.dx, b.cells[v].y + s.dy, b.cells[v].z + s.dz};
        edges.emplace_back(v, static_cast<Vertex>(b.vertex[grid.index(t)]));
        weights.push_back({s.cost});
      }
  b.graph = BoostGraph(boost::edges_are_sorted, edges.begin(), edges.end(), weights.begin(),
                       static_cast<Vertex>(b.cells.size()));
  return b;
}

struct GoalReached {};

struct GoalVisitor : boost::default_astar_visitor {
  Vertex goal;
  std::uint64_t* examined;
  template <class G>
  void examine_vertex(Vertex u, const G&) {
    ++*examined;
    if (u == goal) throw GoalReached{};
  }
};

struct OctileHeuristic : boost::astar_heuristic<BoostGraph, double> {
  const std::vector<Cell>* cells;
  Cell goal;
  double operator()(Vertex v) const {
    const Cell& c = (*cells)[v];
    return octileDistance(c.x - goal.x, c.y - goal.y, c.z - goal.z);
  }
};

// Runs boost::astar_search (the variant that initialises its maps, as a user calls it);
// returns the path length (-1 if none) and adds the examined vertices to `expansions`.
double boostAStar(const BoostGrid& b, const OccupancyGrid& grid, const Query& q,
                  std::vector<Vertex>& pred, std::vector<double>& dist, std::vector<double>& cost,
                  std::vector<boost::default_color_type>& color, std::uint64_t& expansions) {
  const Vertex s = static_cast<Vertex>(b.vertex[grid.index(q.start)]);
  const Vertex t = static_cast<Vertex>(b.vertex[grid.index(q.goal)]);
  GoalVisitor vis;
  vis.goal = t;
  vis.examined = &expansions;
  OctileHeuristic h;
  h.cells = &b.cells;
  h.goal = q.goal;
  try {
    boost::astar_search(b.graph, s, h,
                        boost::visitor(vis)
                            .predecessor_map(boost::make_iterator_property_map(
                                pred.begin(), boost::get(boost::vertex_index, b.graph)))
                            .distance_map(boost::make_iterator_property_map(
                                dist.begin(), boost::get(boost::vertex_index, b.graph)))
                            .rank_map(boost::make_iterator_property_map(
                                cost.begin(), boost::get(boost::vertex_index, b.graph)))
                            .color_map(boost::make_iterator_property_map(
                                color.begin(), boost::get(boost::vertex_index, b.graph)))
                            .weight_map(boost::get(&EdgeWeight::w, b.graph)));
  } catch (const GoalReached&) {
    return dist[t];
  }
  return -1.0;
}

struct Comparison {
  double ours_ms = 0, boost_ms = 0;
  double ours_expansions = 0, boost_expansions = 0;
  int queries = 0, mismatches = 0;
};

Comparison compare(const OccupancyGrid& grid, const std::vector<Query>& queries,
                   const GridMoves& moves) {
  const BoostGrid b = buildBoostGrid(grid, moves);
  const std::size_t n = b.cells.size();
  std::vector<Vertex> pred(n);
  std::vector<double> dist(n), cost(n);
  std::vector<boost::default_color_type> color(n);
  AStar astar(AStar::Options{moves, 1.0});
  Comparison c;
  for (const Query& q : queries) {
    GridQuery gq;
    gq.grid = &grid;
    gq.start = q.start;
    gq.goal = q.goal;
    gq.time_limit_s = 600;
    double t0 = cpuMs();
    const GridPlanResult ours = astar.solveGrid(gq, StopToken::untimed());
    c.ours_ms += cpuMs() - t0;
    c.ours_expansions += ours.counters.at("expansions");
    std::uint64_t examined = 0;
    t0 = cpuMs();
    const double boost_length = boostAStar(b, grid, q, pred, dist, cost, color, examined);
    c.boost_ms += cpuMs() - t0;
    c.boost_expansions += static_cast<double>(examined);
    const double ours_length = ours.success ? ours.length : -1.0;
    if (std::abs(ours_length - boost_length) > 1e-9 * std::max(1.0, boost_length)) ++c.mismatches;
    ++c.queries;
  }
  return c;
}

// A 3D grid of random boxes (fixed seed) filling about 20% of the cells.
OccupancyGrid randomBoxWorld(int nx, int ny, int nz, std::uint64_t seed) {
  OccupancyGrid g(nx, ny, nz);
  std::mt19937_64 rng(seed);
  const std::size_t target = g.cellCount() / 5;
  while (g.blockedCount() < target) {
    const int sx = 2 + int(rng() % (nx / 15)), sy = 2 + int(rng() % (ny / 15)),
              sz = 2 + int(rng() % (nz / 2));
    const int x0 = int(rng() % (nx - sx)), y0 = int(rng() % (ny - sy)), z0 = int(rng() % (nz - sz));
    for (int z = z0; z < z0 + sz; ++z)
      for (int y = y0; y < y0 + sy; ++y)
        for (int x = x0; x < x0 + sx; ++x) g.setBlocked(x, y, z, true);
  }
  return g;
}

// Queries between random free cells at least half the grid's diagonal apart.
std::vector<Query> farQueries(const OccupancyGrid& g, int count, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  const double min_dist =
      0.5 * std::sqrt(double(g.nx()) * g.nx() + double(g.ny()) * g.ny() + double(g.nz()) * g.nz());
  auto freeCell = [&] {
    for (;;) {
      const Cell c{int(rng() % g.nx()), int(rng() % g.ny()), int(rng() % g.nz())};
      if (g.free(c)) return c;
    }
  };
  std::vector<Query> out;
  while (static_cast<int>(out.size()) < count) {
    const Query q{freeCell(), freeCell()};
    if (euclideanDistance(q.start.x - q.goal.x, q.start.y - q.goal.y, q.start.z - q.goal.z) >=
        min_dist)
      out.push_back(q);
  }
  return out;
}

void addFigures(Section& s, const std::string& prefix, const Comparison& c) {
  s.figures.push_back({prefix + "_queries", double(c.queries), ""});
  s.figures.push_back({prefix + "_ours_total_ms", c.ours_ms, "ms"});
  s.figures.push_back({prefix + "_boost_total_ms", c.boost_ms, "ms"});
  s.figures.push_back({prefix + "_speedup_total_time", c.boost_ms / c.ours_ms, "x"});
  const double ours_rate = c.ours_expansions / (c.ours_ms / 1000.0);
  const double boost_rate = c.boost_expansions / (c.boost_ms / 1000.0);
  s.figures.push_back({prefix + "_ours_expansions_per_s", ours_rate, "1/s"});
  s.figures.push_back({prefix + "_boost_expansions_per_s", boost_rate, "1/s"});
  s.figures.push_back({prefix + "_speedup_expansions_per_s", ours_rate / boost_rate, "x"});
  s.figures.push_back({prefix + "_length_mismatches", double(c.mismatches), ""});
}

}  // namespace

Section benchGridAStarVsBoost(bool quick) {
  Section s;
  s.name = "grid_astar_vs_boost";
  const GridMoves moves2d{8, false}, moves3d{26, false};

  // 2D: the bundled 256x256 MovingAI city map (Berlin_0_256), every k-th scenario line so all
  // buckets appear.
  std::pair<std::string, std::string> files{
      std::string(COSIM_SOURCE_DIR) + "/tests/data/movingai/Berlin_0_256.map",
      std::string(COSIM_SOURCE_DIR) + "/tests/data/movingai/Berlin_0_256.map.scen"};
  const OccupancyGrid map = readMovingAIMap(files.first);
  const auto lines = readMovingAIScenario(files.second);
  const std::size_t wanted = quick ? 100 : 1000;
  const std::size_t stride = std::max<std::size_t>(1, lines.size() / wanted);
  std::vector<Query> map_queries;
  for (std::size_t i = 0; i < lines.size() && map_queries.size() < wanted; i += stride)
    map_queries.push_back(
        {{lines[i].start_x, lines[i].start_y, 0}, {lines[i].goal_x, lines[i].goal_y, 0}});
  const Comparison c2 = compare(map, map_queries, moves2d);
  addFigures(s, "map", c2);

  // 3D: random boxes, 26-connected without corner cutting.
  const OccupancyGrid cube =
      quick ? randomBoxWorld(100, 100, 25, 7) : randomBoxWorld(200, 200, 50, 7);
  const Comparison c3 = compare(cube, farQueries(cube, quick ? 4 : 12, 11), moves3d);
  addFigures(s, "grid3d", c3);

  const double worst = std::min({c2.boost_ms / c2.ours_ms, c3.boost_ms / c3.ours_ms});
  s.note = "A* vs boost::astar_search on " +
           std::filesystem::path(files.first).filename().string() + " (" +
           std::to_string(map.nx()) + "x" + std::to_string(map.ny()) + ", " +
           std::to_string(c2.queries) + " scen lines) and a " + std::to_string(cube.nx()) + "x" +
           std::to_string(cube.ny()) + "x" + std::to_string(cube.nz()) +
           " 3D grid; lowest total-time speedup " + std::to_string(worst).substr(0, 4) + "x " +
           (worst >= 3.0 ? "(target >= 3x met)" : "(target >= 3x NOT met)") +
           (c2.mismatches + c3.mismatches == 0 ? ", lengths identical" : ", LENGTH MISMATCHES");
  return s;
}

}  // namespace cosim::bench
