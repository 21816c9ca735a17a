#include "control/figure_eight_reference.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace cosim {

namespace {

// The rate profile of the ramp up, s(u) = 10u^3 - 15u^4 + 6u^5 on u in [0, 1], its integral and
// derivatives: phi_dot = w s(t / T).
struct Smoothstep {
  double integral, value, d1, d2, d3;
};
Smoothstep smoothstep(double u) {
  const double u2 = u * u, u3 = u2 * u;
  return {2.5 * u3 * u - 3.0 * u3 * u2 + u3 * u3,  // int_0^u s
          10.0 * u3 - 15.0 * u3 * u + 6.0 * u3 * u2, 30.0 * u2 - 60.0 * u3 + 30.0 * u2 * u2,
          60.0 * u - 180.0 * u2 + 120.0 * u3, 60.0 - 360.0 * u + 360.0 * u2};
}

}  // namespace

FigureEightReference::FigureEightReference(const FigureEightShape& shape)
    : shape_(shape), rate_(shape.peak_speed / (shape.amplitude * std::sqrt(2.0))) {
  // Each ramp turns the phase by w T / 2 (the smoothstep averages 1/2).
  const double turns = 2.0 * M_PI * shape.laps;
  cruise_time_ = (turns - rate_ * shape.ramp) / rate_;
  if (cruise_time_ < 0.0)
    throw std::invalid_argument("figure eight: the ramps alone exceed the laps asked for");
}

FigureEightReference::Phase FigureEightReference::phase(double t) const {
  const double T = shape_.ramp, w = rate_;
  const double end = duration();
  Phase p;
  if (t <= 0.0) return p;
  if (t < T) {  // speeding up
    const Smoothstep s = smoothstep(t / T);
    return {w * T * s.integral, w * s.value, w * s.d1 / T, w * s.d2 / (T * T),
            w * s.d3 / (T * T * T)};
  }
  const double total = 2.0 * M_PI * shape_.laps;
  if (t < T + cruise_time_) return {0.5 * w * T + w * (t - T), w, 0, 0, 0};
  if (t < end) {  // slowing down: the mirror image of the ramp up
    const Smoothstep s = smoothstep((end - t) / T);
    return {total - w * T * s.integral, w * s.value, -w * s.d1 / T, w * s.d2 / (T * T),
            -w * s.d3 / (T * T * T)};
  }
  p.phi = total;
  return p;
}

FlatReference FigureEightReference::reference(double t, const VehicleState&) {
  finished_ = t >= duration();
  const Phase ph = phase(t);
  const double A = shape_.amplitude, B = 0.5 * A;
  const double s1 = std::sin(ph.phi), c1 = std::cos(ph.phi);
  const double s2 = std::sin(2.0 * ph.phi), c2 = std::cos(2.0 * ph.phi);
  // d^k p / d phi^k.
  const Eigen::Vector3d p0(A * s1, B * s2, 0.0), p1(A * c1, 2.0 * B * c2, 0.0),
      p2(-A * s1, -4.0 * B * s2, 0.0), p3(-A * c1, -8.0 * B * c2, 0.0),
      p4(A * s1, 16.0 * B * s2, 0.0);
  const double v = ph.d1, a = ph.d2, j = ph.d3, s = ph.d4;
  FlatReference ref;
  ref.position = shape_.centre + p0;
  ref.velocity = p1 * v;
  ref.acceleration = p2 * v * v + p1 * a;
  ref.jerk = p3 * v * v * v + 3.0 * p2 * v * a + p1 * j;
  ref.snap = p4 * v * v * v * v + 6.0 * p3 * v * v * a + p2 * (3.0 * a * a + 4.0 * v * j) + p1 * s;
  return ref;
}

}  // namespace cosim
