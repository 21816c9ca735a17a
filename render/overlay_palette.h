#pragma once
// The colours of everything the renderer and the figures draw on top of the world, in one
// place so a video frame and a figure of the same run agree.
#include <Eigen/Core>
#include <string>

namespace cosim {

// Planned path of a single vehicle; with several vehicles each has its own (agentColour).
inline const Eigen::Vector3f kPlannedPathColour{1.0f, 0.3f, 0.05f};
// The reference trajectory the controller tracked (a thin dashed line).
inline const Eigen::Vector3f kReferenceColour{0.12f, 0.12f, 0.14f};
inline const Eigen::Vector3f kStartColour{0.1f, 0.75f, 0.2f};
inline const Eigen::Vector3f kGoalColour{0.9f, 0.1f, 0.1f};
// The arrow showing where a vehicle heads (magenta: apart from the paths, the error scale and
// the grey world).
inline const Eigen::Vector3f kHeadingColour{0.85f, 0.1f, 0.75f};

// One colour per agent, eight in turn: Okabe & Ito's colour-blind-safe vermillion, sky blue and
// reddish purple ("Color Universal Design", 2008), then plum, crimson, pink, brown and grey.
// None is a colour of the error scale (errorColour) or the heading arrow, so a vehicle's colour
// is never read as an error. With one agent, the planned path keeps kPlannedPathColour.
Eigen::Vector3f agentColour(std::size_t agent);

// The flown trail's colour for a tracking error as a fraction of the colour scale (0..1,
// clamped): the viridis map (van der Walt & Smith, matplotlib 2015), perceptually uniform and
// readable in grey print.
Eigen::Vector3f errorColour(double fraction);

// "#rrggbb" for gnuplot and HTML.
std::string hexColour(const Eigen::Vector3f& rgb);

// The colour scale's upper end: the largest error, but at least `floor`, rounded up to 1, 2 or
// 5 x 10^k, so the scale's labels are round numbers.
double errorScaleMax(double max_error, double floor = 0.0);

// The floor of a run's error colour scale: a quarter of the goal tolerance (0.05 m at the
// default 0.2 m). Errors that small do not decide whether a run reaches its goal; a scale
// autoscaled below it (0.0005 m in calm air) paints sensor noise as if it were signal.
double errorScaleFloor(double goal_tolerance);

}  // namespace cosim
