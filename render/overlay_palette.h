#pragma once
// The visual language: the colours of everything the video, final.png, the figures and
// viewer.html draw on top of the world, and the rule for the error colour scale, in one place so
// that every picture of a run agrees (docs/rendering.md, "What the colours mean"). viewer.html
// reads them from its data (visualLanguageJson), not from colours of its own.
#include <Eigen/Core>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "render/vehicle_palette.h"
#include "sim/error_reference.h"

namespace cosim {

// Planned path of a single vehicle; with several vehicles each has its own (vehicleColour).
inline const Eigen::Vector3f kPlannedPathColour{1.0f, 0.3f, 0.05f};
// A single vehicle's flown path where it is not coloured by error (its error over time in
// figures/error, viewer.html with the error layer off): a dark blue, apart from the orange plan.
inline const Eigen::Vector3f kFlownPathColour{0.13f, 0.35f, 0.65f};
// The state estimate's position (viewer.html's estimate layer): a sky blue, apart from the
// plan's orange, the flown path's dark blue and the start's green.
inline const Eigen::Vector3f kEstimateColour{0.0f, 0.62f, 0.9f};
// The reference trajectory the controller tracked (a thin dashed line).
inline const Eigen::Vector3f kReferenceColour{0.12f, 0.12f, 0.14f};
inline const Eigen::Vector3f kStartColour{0.1f, 0.75f, 0.2f};
inline const Eigen::Vector3f kGoalColour{0.9f, 0.1f, 0.1f};
// The arrow showing where a vehicle heads (magenta: apart from the paths, the error scale and
// the grey world).
inline const Eigen::Vector3f kHeadingColour{0.85f, 0.1f, 0.75f};

// Obstacles in the figures and plan pictures (gnuplot): a blue-grey fill with a darker edge.
inline constexpr const char* kObstacleFill = "#9aa3b0";
inline constexpr const char* kObstacleEdge = "#5b6473";

// The flown trail's colour for a tracking error as a fraction of the colour scale (0..1,
// clamped): the viridis map (van der Walt & Smith, matplotlib 2015), perceptually uniform and
// readable in grey print.
Eigen::Vector3f errorColour(double fraction);

// "#rrggbb" for gnuplot and HTML.
std::string hexColour(const Eigen::Vector3f& rgb);

// The colour scale's upper end: the largest error, but at least `floor`, rounded up to 1, 1.5,
// 2, 2.5, 3, 4, 5, 6 or 8 x 10^k, so the scale's label is a readable number and the largest
// error takes at least two thirds of the scale.
double errorScaleMax(double max_error, double floor = 0.0);

// The floor of a run's error colour scale: a quarter of the goal tolerance (0.05 m at the
// default 0.2 m). Errors that small do not decide whether a run reaches its goal; a scale
// autoscaled below it (0.0005 m in calm air) paints sensor noise as if it were signal.
double errorScaleFloor(double goal_tolerance);

// Each vehicle's error scale top: vehicles whose errors are measured against the same kind of
// reference share one, errorScaleMax of their largest error with errorScaleFloor(goal_tolerance).
// errors: per vehicle, per sample.
std::vector<double> errorScaleTops(const std::vector<ErrorReference>& references,
                                   const std::vector<std::vector<double>>& errors,
                                   double goal_tolerance);

// The colours above as "#rrggbb" for viewer.html: planned, reference, flown, estimate, start,
// goal, heading, the error scale's stops (error_stops, 0 to 1 evenly) and the first `vehicles`
// vehicle colours (vehicles).
nlohmann::json visualLanguageJson(std::size_t vehicles);

}  // namespace cosim
