#pragma once
// Reading a given reference from a CSV file; its header says which of two formats it is:
//   duration,x^0,...,x^7,y^0,...,y^7,z^0,...,z^7,yaw^0,...,yaw^7
//       uav_trajectories polynomial pieces, one per row (control/piecewise_polynomial_reference.h),
//       as Crazyswarm uploads them; a trailing comma on each line (as those tools write) is fine;
//   t,x,y,z  or  t,x,y,z,yaw
//       samples (s, m, rad), interpolated by a clamped cubic spline (control/sampled_reference.h);
//       the first row's time is the reference's start.
// Blank lines are skipped, fields may have spaces around them, line ends may be CRLF.
#include <cstddef>
#include <cstdint>
#include <string>

#include "control/piecewise_polynomial_reference.h"

namespace cosim {

// At most this many pieces (polynomial rows, or sample intervals). The Crazyflie's trajectory
// memory holds about 30 pieces and a sampled flight at 100 Hz of this many rows lasts 17
// minutes; more is surely a wrong file. At the cap the pieces take 27 MB of memory (264 bytes
// each) and a reference's piece lookup stays a binary search of 17 steps.
constexpr std::size_t kMaxReferencePieces = 100000;
// 100 000 rows of 33 numbers of up to 20 characters.
constexpr std::uintmax_t kMaxReferenceFileBytes = 64u << 20;
// The longest reference (as written, before its timescale): a day, sim.max_time's own limit.
constexpr double kMaxReferenceDuration = 86400.0;

// Which format a file was in.
enum class ReferenceFormat { PolynomialPieces, Samples };
const char* referenceFormatName(ReferenceFormat format);  // "polynomial pieces", "samples"

struct ReferenceFile {
  ReferenceFormat format = ReferenceFormat::PolynomialPieces;
  PiecewisePolynomialReference reference;  // unplaced (timescale 1, no offset)
};

// Throws InputError(file, "line N" or "line N, column C", problem) for anything else: an empty
// file, an unknown or wrong header, a row with another number of values than the header, a value
// that is not a finite number, a duration that is not > 0, times that do not increase, too few
// rows, more than kMaxReferencePieces, a reference longer than kMaxReferenceDuration.
ReferenceFile parseReferenceText(const std::string& text, const std::string& file);
// The same from a file (a regular file of at most kMaxReferenceFileBytes).
ReferenceFile readReferenceFile(const std::string& path);

}  // namespace cosim
