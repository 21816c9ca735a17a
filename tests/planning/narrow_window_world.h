#pragma once
// A 0.2 m wall across a 30 x 20 x 10 m room with one square window of 1.2 m: the narrow passage
// on which RRT-Connect with its old 2000-node cap failed (3 of 10 seeds solved). Start
// and goal lie on either side, high and low, off the window's axis.
#include "planning/planner.h"

namespace cosim {

// The window's centre.
inline Eigen::Vector3d narrowWindowCentre() {
  return {15, 10, 5};
}

inline World narrowWindowWorld(double window = 1.2) {
  World w;
  w.bounds_min = {0, 0, 0};
  w.bounds_max = {30, 20, 10};
  const Eigen::Vector3d c = narrowWindowCentre();
  const double thick = 0.2, h = window / 2;
  auto wall = [&](double y0, double y1, double z0, double z1) {
    Obstacle o;
    o.pos = {c.x(), (y0 + y1) / 2, (z0 + z1) / 2};
    o.size = {thick, y1 - y0, z1 - z0};
    w.obstacles.push_back(o);
  };
  wall(0, 20, 0, c.z() - h);                  // below the window
  wall(0, 20, c.z() + h, 10);                 // above
  wall(0, c.y() - h, c.z() - h, c.z() + h);   // left
  wall(c.y() + h, 20, c.z() - h, c.z() + h);  // right
  return w;
}

inline PlanningProblem throughNarrowWindow(const World& w, double inflation) {
  PlanningProblem p;
  p.world = &w;
  p.start = {3, 16, 2};
  p.goal = {27, 16, 8};
  p.inflation = inflation;
  return p;
}

}  // namespace cosim
