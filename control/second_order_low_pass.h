#pragma once
// A second-order low-pass filter, H(s) = w_c^2 / (s^2 + 2 zeta w_c s + w_c^2), with zeta =
// 1/sqrt(2) by default (Butterworth: maximally flat, -3 dB at the cutoff w_c), kept as the state
// (y, y') of that ODE and advanced by its exact discretisation for an input held over the step
// (zero-order hold; the matrix exponential in closed form below).
//
// Why this form: the incremental (INDI) controllers of Tal and Karaman 2021 need the filtered
// signals and the derivative of the filtered gyro; the state y' is that derivative, exact, with
// no finite difference of a noisy signal. Filtering every fed-back signal through the same
// filter keeps them synchronised (the same delay on the measured thrust and on the measured
// acceleration it produced), which is what makes the increments consistent.
#include <cmath>
#include <type_traits>

namespace cosim {

// T: double or a fixed-size Eigen vector (anything with +, - and scalar *).
template <typename T>
class SecondOrderLowPass {
 public:
  // cutoff_hz: w_c / (2 pi); damping: zeta, in (0, 1).
  explicit SecondOrderLowPass(double cutoff_hz = 30.0, double damping = M_SQRT1_2)
      : w_c_(2.0 * M_PI * cutoff_hz), zeta_(damping) {}

  // Starts at rest on `value` (y = value, y' = 0): no start-up transient from zero.
  void reset(const T& value) {
    y_ = value;
    y_dot_ = zero();
    initialised_ = true;
  }
  // Forgets the state: the next update starts at rest on its input.
  void clear() {
    y_ = y_dot_ = zero();
    initialised_ = false;
  }
  bool initialised() const { return initialised_; }

  // Advances the filter by dt with input u held over the step; returns y. The first call on a
  // filter never reset starts it at rest on u.
  const T& update(const T& u, double dt) {
    if (!initialised_) {
      reset(u);
      return y_;
    }
    if (dt != dt_) discretise(dt);
    // x+ = Phi x + Gamma u with x = (y, y'); Gamma = A^-1 (Phi - I) B = (1 - Phi00, -Phi10),
    // which gives unit DC gain exactly.
    const T y = phi_[0][0] * y_ + phi_[0][1] * y_dot_ + (1.0 - phi_[0][0]) * u;
    const T y_dot = phi_[1][0] * y_ + phi_[1][1] * y_dot_ - phi_[1][0] * u;
    y_ = y;
    y_dot_ = y_dot;
    return y_;
  }

  const T& value() const { return y_; }
  // dy/dt of the filter's output: the filtered derivative of the input.
  const T& derivative() const { return y_dot_; }
  double cutoffHz() const { return w_c_ / (2.0 * M_PI); }

 private:
  // Phi = exp(A dt) for A = [0 1; -w^2 -2 zeta w]: with s = zeta w and w_d = w sqrt(1 - zeta^2),
  // exp(A t) = e^{-s t} [cos + s/w_d sin, sin/w_d; -w^2/w_d sin, cos - s/w_d sin] (w_d t).
  void discretise(double dt) {
    dt_ = dt;
    const double s = zeta_ * w_c_;
    const double w_d = w_c_ * std::sqrt(1.0 - zeta_ * zeta_);
    const double e = std::exp(-s * dt), c = std::cos(w_d * dt), sn = std::sin(w_d * dt);
    phi_[0][0] = e * (c + s / w_d * sn);
    phi_[0][1] = e * sn / w_d;
    phi_[1][0] = -e * w_c_ * w_c_ / w_d * sn;
    phi_[1][1] = e * (c - s / w_d * sn);
  }

  static T zero() {
    if constexpr (std::is_arithmetic_v<T>)
      return T(0);
    else
      return T::Zero();
  }

  double w_c_, zeta_;
  double dt_ = -1.0;
  double phi_[2][2] = {{1.0, 0.0}, {0.0, 1.0}};
  T y_ = zero(), y_dot_ = zero();
  bool initialised_ = false;
};

}  // namespace cosim
