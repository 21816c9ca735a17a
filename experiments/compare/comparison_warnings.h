#pragma once
// What compare-real warns of (on the console and in compare.json's `warnings`): a placement that
// took, or left, something large. A fitted time shift above kLargeTimeShiftS may be a lag of the
// real flight taken out of its error (when the log's clock is the run's); a mean offset of the
// real flight from the simulated one above kLargeOffsetM on an axis is either fitted away (not in
// the real error) or kept in it, and the user should know which.
#include <string>
#include <vector>

#include "experiments/compare/flight_comparison.h"

namespace cosim {

std::vector<std::string> comparisonWarnings(const FlightComparison& c);

}  // namespace cosim
