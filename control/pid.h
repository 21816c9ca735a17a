#pragma once
// A PID term on one axis with integral anti-windup: the integral is clamped to +-i_limit, and
// it is frozen while the loop's output is saturated in the direction the error pushes
// (conditional integration), so it cannot wind up during long saturations.
#include <algorithm>

namespace cosim {

struct PidGains {
  double kp = 0.0, ki = 0.0, kd = 0.0;
  double i_limit = 0.0;  // bound on |ki * integral|, in output units
};

class Pid {
 public:
  Pid() = default;
  explicit Pid(const PidGains& g) : g_(g) {}
  void reset() { integral_ = 0.0; }
  // error and its derivative (supplied, to avoid differentiating a noisy signal);
  // saturated_sign: +1/-1 if the output was clamped high/low last step, 0 otherwise.
  double update(double error, double error_rate, double dt, int saturated_sign = 0) {
    const bool pushing_into_limit = (saturated_sign > 0 && error > 0) ||
                                    (saturated_sign < 0 && error < 0);
    if (!pushing_into_limit && g_.ki > 0.0) {
      integral_ += error * dt;
      const double bound = g_.i_limit / g_.ki;
      integral_ = std::clamp(integral_, -bound, bound);
    }
    return g_.kp * error + g_.ki * integral_ + g_.kd * error_rate;
  }
  double integral() const { return integral_; }

 private:
  PidGains g_;
  double integral_ = 0.0;
};

}  // namespace cosim
