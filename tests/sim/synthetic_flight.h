#pragma once
// For estimation tests: the exact motion of a quadrotor on an analytic trajectory, with what an
// ideal IMU on it would read. The attitude comes from differential flatness (Mellinger and
// Kumar, "Minimum snap trajectory generation and control for quadrotors", ICRA 2011, eqs. 6-7):
// the body z axis along the thrust direction a + g e3, yaw held at 0 (x_B normal to the world
// y axis), the body rates from the jerk, and the body-frame specific force
// R^T (a + g e3) = (0, 0, |a + g e3|). World frame z up, gravity (0, 0, -g).
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>

namespace cosim::test {

struct TruthSample {
  double t = 0.0;
  Eigen::Vector3d position, velocity, acceleration, jerk;
  Eigen::Quaterniond attitude;            // body to world
  Eigen::Vector3d angular_velocity_body;  // rad/s
  Eigen::Vector3d specific_force_body;    // m/s^2
};

class SyntheticFlight {
 public:
  static constexpr double kGravity = 9.81;

  // Holding still at `position`.
  static SyntheticFlight hover(const Eigen::Vector3d& position) {
    return SyntheticFlight(position, 0.0, 0.0);
  }
  // x = A sin(w t), y = (A / 2) sin(2 w t) about `centre`, z constant; the speed peaks at the
  // crossing (t = 0, one period later, ...) at sqrt(2) A w, so w = peak_speed / (sqrt(2) A).
  static SyntheticFlight figureEight(const Eigen::Vector3d& centre, double amplitude,
                                     double peak_speed) {
    return SyntheticFlight(centre, amplitude, peak_speed / (std::sqrt(2.0) * amplitude));
  }

  double period() const { return w_ > 0.0 ? 2.0 * M_PI / w_ : INFINITY; }

  TruthSample at(double t) const {
    const double A = a_, w = w_;
    const double s1 = std::sin(w * t), c1 = std::cos(w * t);
    const double s2 = std::sin(2 * w * t), c2 = std::cos(2 * w * t);
    TruthSample s;
    s.t = t;
    s.position = centre_ + Eigen::Vector3d(A * s1, 0.5 * A * s2, 0.0);
    s.velocity = {A * w * c1, A * w * c2, 0.0};
    s.acceleration = {-A * w * w * s1, -2.0 * A * w * w * s2, 0.0};
    s.jerk = {-A * w * w * w * c1, -4.0 * A * w * w * w * c2, 0.0};

    // Thrust direction and the yaw-zero body frame (Mellinger and Kumar eq. 6 with psi = 0).
    const Eigen::Vector3d thrust = s.acceleration + kGravity * Eigen::Vector3d::UnitZ();
    const double u = thrust.norm();
    const Eigen::Vector3d z_b = thrust / u;
    const Eigen::Vector3d y_c = Eigen::Vector3d::UnitY();
    const Eigen::Vector3d x_b = y_c.cross(z_b).normalized();
    const Eigen::Vector3d y_b = z_b.cross(x_b);
    Eigen::Matrix3d R;
    R << x_b, y_b, z_b;
    s.attitude = Eigen::Quaterniond(R);

    // Body rates from the rotating axes, R_dot = R [w]x: w_x = -y_b . z_b_dot and
    // w_y = x_b . z_b_dot (Mellinger and Kumar eq. 7, z_b_dot = h_w), w_z = y_b . x_b_dot.
    // (w_z is not zero for a constant yaw once the vehicle both rolls and pitches.)
    const Eigen::Vector3d z_b_dot = (s.jerk - z_b.dot(s.jerk) * z_b) / u;
    const Eigen::Vector3d n = y_c.cross(z_b);
    const Eigen::Vector3d x_b_dot =
        (y_c.cross(z_b_dot) - x_b.dot(y_c.cross(z_b_dot)) * x_b) / n.norm();
    s.angular_velocity_body = {-y_b.dot(z_b_dot), x_b.dot(z_b_dot), y_b.dot(x_b_dot)};
    s.specific_force_body = {0.0, 0.0, u};
    return s;
  }

 private:
  SyntheticFlight(const Eigen::Vector3d& centre, double amplitude, double w)
      : centre_(centre), a_(amplitude), w_(w) {}

  Eigen::Vector3d centre_;
  double a_;  // m
  double w_;  // rad/s
};

}  // namespace cosim::test
