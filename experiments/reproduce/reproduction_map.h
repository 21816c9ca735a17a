#pragma once
// The rebuilt maps of a thesis reproduction, drawn beside its report as NAME_mapK.png and .svg
// (gnuplot, render/gnuplot.h): the obstacles, the start, the goal and the best path of each
// method on that map, seen from above. Grid maps are drawn cell by cell (a 3D grid as its
// footprint, each column shaded by the top of its highest blocked cell, with a scale: a wall on
// a slab shows apart from the slab); polygon maps (MAKLINK) as filled polygons.
#include <Eigen/Core>
#include <filesystem>
#include <string>
#include <vector>

#include "planning/grid/occupancy_grid.h"

namespace cosim::reproduce {

struct MapPath {
  std::string label;                    // the method, as the report's tables name it
  std::vector<Eigen::Vector2d> points;  // in the map's units, in order
};

struct ReproductionMap {
  std::string title;           // the map's name and how it was rebuilt
  const char* unit = "cells";  // the axes' unit (a literal)
  Eigen::Vector2d lo = Eigen::Vector2d::Zero(), hi = Eigen::Vector2d::Zero();  // drawn extent
  // Filled rectangles {x0, y0, x1, y1} (2D maps).
  std::vector<Eigen::Vector4d> blocks;
  // 3D maps seen from above: rectangles of columns whose obstacles reach up to `top` (in `unit`,
  // above the grid's floor), shaded from light (low) to dark (height_max).
  struct HeightBlock {
    Eigen::Vector4d rect;
    double top;
  };
  std::vector<HeightBlock> height_blocks;
  double height_max = 0;
  std::vector<std::vector<Eigen::Vector2d>> polygons;
  std::vector<Eigen::Vector2d> moving_obstacle_starts;  // drawn as hollow squares
  Eigen::Vector2d start = Eigen::Vector2d::Zero(), goal = Eigen::Vector2d::Zero();
  // Other agents' starts and goals (multi-robot maps), drawn like start and goal.
  std::vector<Eigen::Vector2d> more_starts, more_goals;
  std::vector<MapPath> paths;
};

// A map over `grid` in cell units (cell (x, y) spans [x, x+1) x [y, y+1)), with rows of blocked
// cells merged into rectangles (3D: rows of columns with the same top, as height_blocks, tops in
// cells = metres on 1 m grids); start and goal at their cells' centres.
ReproductionMap gridMap(const std::string& title, const OccupancyGrid& grid, const Cell& start,
                        const Cell& goal);

// Cell centres of a cell path (any-angle planners' turning cells are joined by straight lines).
std::vector<Eigen::Vector2d> cellCentres(const std::vector<Cell>& cells);

// Writes out_dir/NAME_map<index>.png and .svg, each atomically (nothing when out_dir is empty);
// returns "NAME_map<index>".
// Throws std::runtime_error if gnuplot fails.
std::string writeReproductionMap(const std::filesystem::path& out_dir, const std::string& name,
                                 int index, const ReproductionMap& map);

// The report's paragraph for its maps: one line per map, "![title](file.png)" and how it was
// rebuilt (`how`, one entry per map, in the order written).
std::string mapFiguresMarkdown(const std::vector<std::string>& files,
                               const std::vector<std::string>& how);

}  // namespace cosim::reproduce
