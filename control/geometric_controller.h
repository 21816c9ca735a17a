#pragma once
// Geometric tracking control on SE(3) (Lee, Leok and McClamroch 2010, "Geometric tracking control
// of a quadrotor UAV on SE(3)", eqs. 15-16), written with z up: the thrust vector follows the
// position and velocity errors plus the reference acceleration, and the attitude error is measured
// on SO(3) (e_R = vee(R_d^T R - R^T R_d) / 2), which stays well defined for large errors such as
// recovering from a 90-degree roll. The desired body rates come from the reference jerk by
// differential flatness (Mellinger and Kumar 2011, eq. 7), so the attitude loop does not lag the
// trajectory.
//
// With drag_compensation, the rotor drag of Faessler, Franchi and Scaramuzza 2018 ("Differential
// flatness of quadrotor dynamics subject to rotor drag for accurate tracking of high-speed
// trajectories", RA-L 3(2); dv/dt = c z_B - g e3 - R D R^T v, D = diag(d_x, d_y, d_z) per unit
// mass from QuadrotorParams::linearDragPerMass) enters the feed-forward: the desired thrust gains
// R D R^T v_ref (the drag the reference velocity will meet; R is the current attitude, through
// which the drag acts, where Faessler et al. use the reference attitude: the two agree on the
// trajectory), and the body rates use the drag-corrected jerk j + R_d D R_d^T a_ref over the
// thrust corrected by (d_x - d_z) z_B . v_ref (their body-rate equations with d_x = d_y, as
// linearDragPerMass gives; the terms in d_x - d_y that couple the rates are left out).
#include "control/flight_controller.h"
#include "control/mixer.h"

namespace cosim {

// Gains in acceleration units: the controller multiplies them by the mass (position) and by the
// inertia (attitude), so the same values suit a 27 g and a 1.5 kg airframe of similar agility.
struct GeometricGains {
  Eigen::Vector3d k_x{6.0, 6.0, 8.0};  // 1/s^2: position error -> acceleration
  Eigen::Vector3d k_v{4.0, 4.0, 5.0};  // 1/s: velocity error -> acceleration
  double k_i = 2.0;                    // 1/s^3: integral of position error (wind, mass errors)
  double i_limit = 2.0;                // m/s^2: bound on the integral's contribution
  // m/s: the integral runs only while the velocity error is below this, i.e. near a steady state
  // (a steady wind); steps, recoveries and manoeuvres would otherwise wind it up into overshoot.
  double i_velocity_zone = 0.3;
  Eigen::Vector3d k_R{140.0, 140.0, 40.0};    // 1/s^2: attitude error -> angular acceleration
  Eigen::Vector3d k_omega{20.0, 20.0, 10.0};  // 1/s: angular velocity error -> angular acceleration
  double max_tilt_deg = 60.0;                 // limit on the commanded thrust vector's tilt
};

class GeometricController : public FlightController {
 public:
  GeometricController(const QuadrotorParams& params, const GeometricGains& gains = {},
                      bool drag_compensation = false);
  static constexpr char kName[] = "geometric";
  std::string name() const override { return kName; }
  void reset() override;
  ControlOutput update(const VehicleState& state, const FlatReference& ref, double dt) override;

  // For logging: the last desired attitude (body to world) and desired body rates.
  const Eigen::Matrix3d& desiredAttitude() const { return R_d_; }
  const Eigen::Vector3d& desiredBodyRates() const { return omega_d_; }

 private:
  QuadrotorParams params_;
  GeometricGains gains_;
  Eigen::Vector3d D_;  // drag per unit mass in the feed-forward, 1/s (zero without compensation)
  Mixer mixer_;
  Eigen::Vector3d integral_ = Eigen::Vector3d::Zero();  // of the position error, m s
  bool saturated_ = false;                              // the mixer gave something up last step
  Eigen::Matrix3d R_d_ = Eigen::Matrix3d::Identity();
  Eigen::Vector3d omega_d_ = Eigen::Vector3d::Zero();
};

class ControllerRegistry;
// Registers geometric (its gains, team margin, ...) in the controller registry.
void registerGeometricController(ControllerRegistry& registry);

}  // namespace cosim
