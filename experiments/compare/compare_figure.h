#pragma once
// The comparison figure, PNG and SVG (gnuplot, render/gnuplot.h), two panels side by side:
// left, the real and simulated flown paths over the reference seen from above (x-y, equal
// axes; the real path in the run's frame and on its clock); right, both position errors over
// the run's time, with their RMSE in the legend.
#include <filesystem>

#include "experiments/compare/flight_comparison.h"

namespace cosim {

// Writes out_base.png and out_base.svg, each atomically. Throws std::runtime_error if gnuplot
// fails.
void writeCompareFigure(const FlightComparison& c, const std::filesystem::path& out_base);

}  // namespace cosim
