#pragma once
// The data files a run's figures plot (render/figures.h), a team's in one file per kind of line
// rather than one per vehicle: gnuplot then draws a 500-vehicle figure with five plot elements,
// not 2500, and each vehicle's colour comes from a column of the file (lc rgb variable).
#include <Eigen/Core>
#include <filesystem>
#include <vector>

#include "run/record/run_record.h"

namespace cosim {

// Rows per vehicle's flown series: all the figures' rows shared out among the vehicles (a
// 500-vehicle team's figures stay as small and as quick to draw as a few vehicles'), at least
// kMinPlotRowsPerVehicle (a trail keeps its shape), at most kMaxPlotRowsPerVehicle.
constexpr std::size_t kMaxPlotRowsPerVehicle = 2500;
constexpr std::size_t kMinPlotRowsPerVehicle = 150;
constexpr std::size_t kPlotRowBudget = 60000;
std::size_t plotRowsPerVehicle(std::size_t vehicles);

// The indices of `count` samples kept, evenly in time, always the first and the last.
std::vector<std::size_t> evenSampleIndices(std::size_t count, std::size_t rows);

// 0xRRGGBB of a colour, for a data file's colour column.
long rgbNumber(const Eigen::Vector3f& rgb);

// The files, written into `dir`:
//   flown.dat:  per vehicle a block of rows "t x y z ref_x ref_y ref_z error rgb" (a blank line
//               between vehicles: gnuplot does not join them; block i is vehicle i's);
//   refs.dat:   the same rows, of the vehicles whose reference is a trajectory only;
//   plans.dat:  per vehicle a block "x y z rgb" of its planned path's points;
//   starts.dat, goals.dat: one row "x y z rgb" per vehicle.
// rgb is each vehicle's colour (render/vehicle_palette.h), or `single` for all of a single
// vehicle's lines but the flown one. Throws StopRequestedError if a stop is requested midway.
struct FigureFiles {
  bool any_reference = false;  // refs.dat has rows
  bool any_plan = false;       // plans.dat has a path of two points or more
  bool any_flown = false;      // flown.dat has rows
  double duration = 0.0;       // the last logged time of any vehicle
};
FigureFiles writeFigureFiles(const RunRecord& record, const std::filesystem::path& dir);

}  // namespace cosim
