#pragma once
// Obstacle-free distances between cells, used as A* heuristics: each is the exact length of the
// shortest move sequence on an empty grid, hence admissible and consistent for its move set.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>

namespace cosim {

// Axis moves only (4- or 6-connected): Manhattan distance.
inline double manhattanDistance(int dx, int dy, int dz) {
  return std::abs(dx) + std::abs(dy) + std::abs(dz);
}

// Moves to all 8 (2D) or 26 (3D) neighbours: with |d1| >= |d2| >= |d3|, the shortest route takes
// d3 body diagonals (sqrt 3), d2 - d3 face diagonals (sqrt 2) and d1 - d2 straight moves. On 2D
// grids (d3 = 0) this is the octile distance of the MovingAI benchmarks. Also a lower bound for
// 18-connected moves, which are a subset of the 26.
inline double octileDistance(int dx, int dy, int dz) {
  int a = std::abs(dx), b = std::abs(dy), c = std::abs(dz);
  if (a < b) std::swap(a, b);
  if (b < c) std::swap(b, c);
  if (a < b) std::swap(a, b);
  constexpr double kSqrt2 = 1.4142135623730951, kSqrt3 = 1.7320508075688772;
  return c * kSqrt3 + (b - c) * kSqrt2 + (a - b);
}

// The same two distances in the exact-integer costs of grid_search_space.h (FixedCost units,
// passed in so that this header stays free of the search types).
inline std::uint64_t manhattanDistanceFixed(int dx, int dy, int dz, std::uint64_t straight) {
  return static_cast<std::uint64_t>(std::abs(dx) + std::abs(dy) + std::abs(dz)) * straight;
}
inline std::uint64_t octileDistanceFixed(int dx, int dy, int dz, std::uint64_t straight,
                                         std::uint64_t face, std::uint64_t body) {
  int a = std::abs(dx), b = std::abs(dy), c = std::abs(dz);
  if (a < b) std::swap(a, b);
  if (b < c) std::swap(b, c);
  if (a < b) std::swap(a, b);
  return static_cast<std::uint64_t>(c) * body + static_cast<std::uint64_t>(b - c) * face +
         static_cast<std::uint64_t>(a - b) * straight;
}

inline double euclideanDistance(int dx, int dy, int dz) {
  return std::sqrt(static_cast<double>(dx) * dx + static_cast<double>(dy) * dy +
                   static_cast<double>(dz) * dz);
}

}  // namespace cosim
