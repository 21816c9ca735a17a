#pragma once
// A time-parametrised trajectory as the controller's reference: position and its derivatives
// (flat outputs, for feed-forward) at time t since the start of the flight.
#include "control/reference_source.h"
#include "planning/trajectory/piecewise_polynomial_trajectory.h"

namespace cosim {

class TrajectoryReference : public ReferenceSource {
 public:
  TrajectoryReference(PiecewisePolynomialTrajectory trajectory, double yaw)
      : trajectory_(std::move(trajectory)), yaw_(yaw) {}
  FlatReference reference(double t, const VehicleState& state) override;
  bool atFinalSetpoint() const override { return finished_; }
  const PiecewisePolynomialTrajectory& trajectory() const { return trajectory_; }

 private:
  PiecewisePolynomialTrajectory trajectory_;
  double yaw_;
  bool finished_ = false;
};

}  // namespace cosim
