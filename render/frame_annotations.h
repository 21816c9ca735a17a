#pragma once
// The 2D parts of a video frame, drawn over the rendered scene with MuJoCo's text and
// rectangle primitives: the run's state (time, speed, error, planner), a legend of the lines,
// and the colour scale of the flown trail.
#include <mujoco/mujoco.h>

#include <Eigen/Core>
#include <string>
#include <vector>

namespace cosim {

struct LegendEntry {
  std::string label;
  Eigen::Vector3f colour;
  bool gradient = false;  // the swatch shows the error colour scale instead
};

class FrameAnnotations {
 public:
  FrameAnnotations(mjrContext* con, mjrRect viewport);

  // Label/value lines in a box at the top left.
  void stateBox(const std::vector<std::pair<std::string, std::string>>& lines);
  // Colour swatches with labels in a box at the bottom left.
  void legend(const std::vector<LegendEntry>& entries);
  // A horizontal viridis bar at the bottom right from 0 to scale_max, with its title.
  void errorScale(double scale_max, const std::string& title);

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
