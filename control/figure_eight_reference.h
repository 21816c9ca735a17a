#pragma once
// A figure-eight reference for tracking studies: the lemniscate of Gerono in a horizontal plane,
//   p(phi) = c + (A sin phi, (A/2) sin 2 phi, 0),
// flown `laps` times from rest at its centre and back to rest there. The phase phi(t) speeds up
// from 0 to its cruise rate w over `ramp` seconds with a quintic smoothstep of the rate (so
// velocity, acceleration and jerk start from zero), cruises, and slows down the same way, ending
// exactly after `laps` turns. The peak speed is A w sqrt(2) (at the centre crossings), so
// w = peak_speed / (A sqrt 2). Every derivative up to snap is exact (chain rule through phi(t)).
#include <Eigen/Core>

#include "control/reference_source.h"

namespace cosim {

struct FigureEightShape {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  double amplitude = 8.0;   // A, m: the figure spans 2A along x and A along y
  double peak_speed = 4.0;  // m/s at the centre crossings
  int laps = 2;
  double ramp = 3.0;  // s to reach (and to leave) the cruise rate
};

class FigureEightReference : public ReferenceSource {
 public:
  // Throws std::invalid_argument if the ramps alone would turn more than `laps` times.
  explicit FigureEightReference(const FigureEightShape& shape);
  FlatReference reference(double t, const VehicleState& state) override;
  bool atFinalSetpoint() const override { return finished_; }
  double duration() const { return 2.0 * shape_.ramp + cruise_time_; }

  // The phase and its first four time derivatives at t.
  struct Phase {
    double phi = 0, d1 = 0, d2 = 0, d3 = 0, d4 = 0;
  };
  Phase phase(double t) const;

 private:
  FigureEightShape shape_;
  double rate_;         // w, rad/s
  double cruise_time_;  // s at the cruise rate
  bool finished_ = false;
};

}  // namespace cosim
