#pragma once
// The 2D parts of a video frame, drawn over the rendered scene with MuJoCo's text and
// rectangle primitives: the run's state (time, speed, error, planner), a legend of the lines,
// and the colour scale of the flown trail.
#include <mujoco/mujoco.h>

#include <Eigen/Core>
#include <string>
#include <utility>
#include <vector>

namespace cosim {

struct LegendEntry {
  LegendEntry(std::string label_, const Eigen::Vector3f& colour_, bool gradient_ = false)
      : label(std::move(label_)), colour(colour_), gradient(gradient_) {}
  std::string label;
  Eigen::Vector3f colour;
  bool gradient = false;                 // the swatch shows the error colour scale instead
  std::vector<Eigen::Vector3f> stripes;  // if given: the swatch shows these colours side by side
};

class FrameAnnotations {
 public:
  FrameAnnotations(mjrContext* con, mjrRect viewport);

  // Each draws a box and returns where (pixels from the bottom left).
  // Label/value lines in a box at the top left.
  mjrRect stateBox(const std::vector<std::pair<std::string, std::string>>& lines);
  // How many state box lines fit in `fraction` of the frame's height.
  int linesFitting(double fraction) const;
  // Colour swatches with labels in a box at the bottom left.
  mjrRect legend(const std::vector<LegendEntry>& entries);
  // A horizontal viridis bar at the bottom right from 0 to scale_max, with its title. slot: 0
  // at the bottom, 1 above it, ... (one scale per kind of error).
  // compact: a bar an eighth of the frame wide instead of a fifth (small frames).
  mjrRect errorScale(double scale_max, const std::string& title, int slot = 0,
                     bool compact = false);

 private:
  int textWidth(const std::string& s) const;
  int lineHeight() const;
  // Text left-aligned in a box whose lower left corner is (x, y), pixels from the bottom left.
  void text(const std::string& s, int x, int y, const Eigen::Vector3f& rgb);
  void box(int x, int y, int w, int h);

  mjrContext* con_;
  mjrRect viewport_;
  int pad_;
};

}  // namespace cosim
