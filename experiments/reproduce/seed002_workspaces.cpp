#include "experiments/reproduce/seed002_workspaces.h"

namespace cosim::reproduce {

Cell Seed002Query::start() const {
  return {static_cast<int>(sx / kSeed002CellCm), static_cast<int>(sy / kSeed002CellCm), 0};
}

Cell Seed002Query::target() const {
  return {static_cast<int>(tx / kSeed002CellCm), static_cast<int>(ty / kSeed002CellCm), 0};
}

const std::vector<Seed002Query>& seed002Queries() {
  static const std::vector<Seed002Query> queries = {
      {5, 50, 400, 450}, {20, 55, 460, 455}, {30, 65, 465, 460}};
  return queries;
}

const double kSeed002Length[3][3][2] = {{{610.34, 618.05}, {655.72, 659.69}, {648.62, 652.08}},
                                        {{919.45, 923.04}, {711.28, 719.48}, {697.80, 707.09}},
                                        {{913.82, 921.03}, {718.59, 722.28}, {698.51, 703.79}}};

std::vector<Seed002Workspace> seed002Workspaces() {
  const std::vector<Seed002Rect> simple = {
      {20, 20, 35, 36}, {46, 14, 56, 44}, {30, 60, 52, 70}, {68, 48, 84, 68}};
  // The pocket around cell (80, 90): north wall, west wall down to the edge, east wall open at
  // the bottom, and an inner wall above the bottom channel, so the way in runs east of the
  // pocket, through the gap under its east wall and back west along the channel.
  std::vector<Seed002Rect> medium = simple;
  for (const Seed002Rect& r : std::vector<Seed002Rect>{
           {60, 70, 88, 71}, {60, 70, 61, 99}, {87, 70, 88, 93}, {69, 93, 88, 94}})
    medium.push_back(r);
  std::vector<Seed002Rect> complex = medium;
  for (const Seed002Rect& r : std::vector<Seed002Rect>{{8, 60, 14, 74},
                                                       {36, 80, 48, 86},
                                                       {66, 20, 78, 26},
                                                       {10, 40, 16, 48},
                                                       {92, 75, 99, 77},
                                                       {90, 56, 94, 58}})
    complex.push_back(r);
  return {{"relatively simple", simple, 20, 30, 20, 50, 47.721, 1522.03},
          {"relatively complex", medium, 25, 45, 35, 80, 648.69, 1865.28},
          {"complex", complex, 30, 50, 50, 100, 972.65, 2560.42}};
}

OccupancyGrid seed002Grid(const Seed002Workspace& w) {
  OccupancyGrid g(100, 100, 1, kSeed002CellCm / 100.0);
  for (const Seed002Rect& r : w.obstacles)
    for (int y = r.y0; y <= r.y1; ++y)
      for (int x = r.x0; x <= r.x1; ++x) g.setBlocked(x, y, 0, true);
  return g;
}

}  // namespace cosim::reproduce
