#pragma once
// The reference of the crazyflie-figure8 study: hover at `start` for `hover_before` seconds, then
// Crazyswarm2's figure8.csv (experiments/scenarios/figure8.csv) relative to `start`, stretched
// by `timescale` as the firmware's startTrajectory does (0.5: twice as fast).
#include "control/reference_source.h"
#include "planning/trajectory/piecewise_polynomial_trajectory.h"

namespace cosim::reproduce {

class FigureEightFlight : public ReferenceSource {
 public:
  FigureEightFlight(double hover_before, double timescale, const Eigen::Vector3d& start);
  FlatReference reference(double t, const VehicleState& state) override;
  bool atFinalSetpoint() const override { return finished_; }
  double figureDuration() const { return figure_.duration(); }

 private:
  PiecewisePolynomialTrajectory figure_;
  double hover_before_;
  Eigen::Vector3d start_;
  bool finished_ = false;
};

}  // namespace cosim::reproduce
