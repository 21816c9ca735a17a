#include "experiments/reproduce/seed002_maklink_map.h"

#include <utility>
#include <vector>

namespace cosim::reproduce {

Seed002MaklinkMap seed002MaklinkMap() {
  // The walls: [0, 333.5] x [0, 333.5] m.
  constexpr double side = 333.5;
  auto poly = [](std::vector<Eigen::Vector2d> v) { return ConvexPolygon{std::move(v)}; };
  std::vector<ConvexPolygon> obstacles = {
      poly({{182.8, 283.6}, {106.6, 304.0}, {89.9, 263.6}, {163.8, 246.0}}),
      poly({{262.5, 132.6}, {192.3, 206.6}, {152.1, 160.2}, {210.3, 99.6}}),
      poly({{264.1, 302.7}, {239.6, 319.5}, {202.6, 277.3}, {223.9, 254.3}}),
      poly({{89.5, 156.2}, {71.9, 241.8}, {38.5, 235.3}, {58.5, 149.1}}),
      poly({{156.7, 121.7}, {118.1, 186.1}, {99.7, 169.4}, {133.9, 110.2}}),
      poly({{88.0, 50.7}, {83.7, 84.7}, {66.4, 82.0}, {71.4, 50.2}}),
      poly({{155.6, 84.0}, {126.9, 93.7}, {93.7, 20.8}, {130.2, 9.8}}),
  };
  return {MaklinkGraph(std::move(obstacles), {0, 0}, {side, side}), {16.7, 16.7}, {316.8, 316.8}};
}

}  // namespace cosim::reproduce
