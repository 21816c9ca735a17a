#pragma once
// A given reference made of polynomial pieces in x, y, z and yaw: the uav_trajectories format
// that Crazyswarm uploads to the Crazyflie (one piece of degree 7 per row, in the piece's local
// time from 0 to its duration), flown as the firmware flies it. Every output is exact: position,
// velocity, acceleration, jerk and snap, yaw, yaw rate and yaw acceleration are the polynomials'
// derivatives.
//
// Timing as crazyflie-firmware's startTrajectory(timescale) (src/modules/interface/pptraj.h,
// piecewise_duration: the sum of the durations times timescale): at time t of the run the pieces
// are evaluated at t / timescale, so a derivative of order k is the piece's divided by
// timescale^k (0.5 flies the same path twice as fast). `offset` moves every point (the vehicle's
// start, for a reference flown relative to it). Before the start the first point is held and
// after the end the last one, both with zero derivatives (the firmware's piecewise_eval holds the
// end point at rest the same way).
#include <Eigen/Core>
#include <vector>

#include "control/reference_source.h"

namespace cosim {

struct ReferencePiece {
  static constexpr int kCoefficients = 8;  // degree 7
  using Coefficients = Eigen::Matrix<double, kCoefficients, 4>;
  double duration = 0.0;  // s, > 0
  // Row k: the coefficient of tau^k, tau in s from the piece's start; columns x, y, z (m) and
  // yaw (rad).
  Coefficients coefficients = Coefficients::Zero();
};

// How a reference is flown: stretched in time and moved.
struct ReferencePlacement {
  double timescale = 1.0;                            // > 0; the durations are multiplied by it
  Eigen::Vector3d offset = Eigen::Vector3d::Zero();  // m, added to every point
};

class PiecewisePolynomialReference : public ReferenceSource {
 public:
  // Throws std::invalid_argument without pieces, for a duration that is not finite and > 0, or
  // a timescale that is not finite and > 0.
  explicit PiecewisePolynomialReference(std::vector<ReferencePiece> pieces,
                                        const ReferencePlacement& placement = {});

  // at(t); atFinalSetpoint() from then on once t has reached the end.
  FlatReference reference(double t, const VehicleState& state) override;
  bool atFinalSetpoint() const override { return finished_; }

  // The reference at time t of the run (s from its start), placed.
  FlatReference at(double t) const;
  // How long it lasts as flown: the pieces' durations times the timescale.
  double duration() const { return file_duration_ * placement_.timescale; }
  const std::vector<ReferencePiece>& pieces() const { return pieces_; }
  const ReferencePlacement& placement() const { return placement_; }
  // The same pieces, flown with another placement.
  PiecewisePolynomialReference placed(const ReferencePlacement& placement) const;
  // Points along the reference at equal times, first and last point included, at most
  // `max_points` (>= 2) and at most one every `min_step` seconds: its path for figures and
  // path.csv.
  std::vector<Eigen::Vector3d> sampledPath(std::size_t max_points, double min_step) const;

 private:
  // The pieces' values and derivatives at time tau of the file (unplaced), held at the ends.
  FlatReference evaluate(double tau) const;

  std::vector<ReferencePiece> pieces_;
  std::vector<double> starts_;  // each piece's start in the file's time
  double file_duration_ = 0.0;
  ReferencePlacement placement_;
  bool finished_ = false;
};

}  // namespace cosim
