#pragma once
// Figures for papers, as PNG and SVG, drawn by gnuplot from generated scripts (render/gnuplot.h).
#include <filesystem>
#include <string>
#include <vector>

#include "run/record/run_record.h"
#include "sim/scenario.h"

namespace cosim {

// The figures of the record of a run of `scenario` in `dir` (created if needed), each as <name>.png
// and <name>.svg:
//   error: tracking error over time per vehicle, with its RMSE and the arrival time;
//   top:   planned path, reference and flown path (coloured by tracking error) over the
//          obstacles seen from above, equal axes;
//   side:  the same seen from the side, along the horizontal axis the flight mostly crosses.
// Returns the names written ("error", "top", "side"). Throws std::runtime_error if gnuplot fails.
std::vector<std::string> writeRunFigures(const Scenario& scenario, const RunRecord& record,
                                         const std::filesystem::path& dir);

}  // namespace cosim
