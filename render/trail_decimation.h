#pragma once
// Which samples of a flown trail to keep as polyline vertices: software rendering pays for
// every capsule, so straight stretches become one segment and curves keep just enough vertices
// to stay within a tolerance of the logged positions (a greedy chord test, in the spirit of
// Douglas & Peucker, Cartographica 10(2), 1973), and the colour (tracking error) may not jump
// by more than a step between vertices.
#include <cstddef>
#include <vector>

#include "sim/run_log.h"

namespace cosim {

struct TrailDecimation {
  double tolerance = 0.01;       // m, largest distance of a skipped sample from its chord
  double max_segment = 1.0;      // m, longest segment (keeps colour gradients smooth)
  double max_error_step = 0.05;  // largest change of the colour value between vertices
};

// Indices of the kept samples, ascending, starting with 0 and ending with the last sample.
// `values` (one per sample) is what colours the trail.
std::vector<std::size_t> decimateTrail(const std::vector<LogSample>& samples,
                                       const std::vector<double>& values,
                                       const TrailDecimation& options);

// The corners of a polyline: runs of points along one straight line (a grid path's cells) become
// one segment, repeated points go. First and last points stay.
std::vector<Eigen::Vector3d> polylineCorners(const std::vector<Eigen::Vector3d>& points);

}  // namespace cosim
