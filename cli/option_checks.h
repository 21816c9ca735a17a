#pragma once
// Checks for the numeric options of the commands. CLI11's own ranges let "nan" through (every
// comparison with NaN is false) and word their complaint about a whole number as a range of
// doubles ("Value 0 not in range 0.000000 to 1797693...").
#include <CLI/CLI.hpp>

namespace cosim::cli {

// A finite number in [lo, hi], written completely ("1e3", not "1e3x").
CLI::Validator numberIn(double lo, double hi);
// A whole number in [lo, hi].
CLI::Validator wholeNumberIn(long lo, long hi);

// A random seed: a whole number from 0 to 2^64 - 1 written in decimal digits only. CLI11 itself
// reads "-1" into an unsigned integer as 2^64 - 1 and "1e23" as whatever the cast makes of it.
CLI::Validator seedNumber();

}  // namespace cosim::cli
