#include "control/sampled_reference.h"

#include <cmath>
#include <stdexcept>

namespace cosim {

namespace {

// The clamped spline's second derivatives M_0..M_n at the samples of one coordinate `y` (end
// slopes 0), by the Thomas algorithm on the system in the header.
std::vector<double> secondDerivatives(const std::vector<double>& h, const std::vector<double>& y) {
  const std::size_t n = h.size();  // intervals; n + 1 unknowns
  std::vector<double> sub(n + 1, 0.0), diag(n + 1), super(n + 1, 0.0), rhs(n + 1);
  diag[0] = 2.0 * h[0];
  super[0] = h[0];
  rhs[0] = 6.0 * (y[1] - y[0]) / h[0];
  for (std::size_t i = 1; i < n; ++i) {
    sub[i] = h[i - 1];
    diag[i] = 2.0 * (h[i - 1] + h[i]);
    super[i] = h[i];
    rhs[i] = 6.0 * ((y[i + 1] - y[i]) / h[i] - (y[i] - y[i - 1]) / h[i - 1]);
  }
  sub[n] = h[n - 1];
  diag[n] = 2.0 * h[n - 1];
  rhs[n] = -6.0 * (y[n] - y[n - 1]) / h[n - 1];
  for (std::size_t i = 1; i <= n; ++i) {  // forward elimination
    const double w = sub[i] / diag[i - 1];
    diag[i] -= w * super[i - 1];
    rhs[i] -= w * rhs[i - 1];
  }
  std::vector<double> m(n + 1);
  m[n] = rhs[n] / diag[n];
  for (std::size_t i = n; i-- > 0;) m[i] = (rhs[i] - super[i] * m[i + 1]) / diag[i];
  return m;
}

}  // namespace

std::vector<ReferencePiece> clampedCubicSplinePieces(const std::vector<ReferenceSample>& samples) {
  if (samples.size() < 2) throw std::invalid_argument("a sampled reference needs two samples");
  const std::size_t n = samples.size() - 1;
  std::vector<double> h(n);
  for (std::size_t i = 0; i < n; ++i) {
    h[i] = samples[i + 1].t - samples[i].t;
    if (!(h[i] > 0.0) || !std::isfinite(h[i]))
      throw std::invalid_argument("a sampled reference's times must increase");
  }
  std::vector<ReferencePiece> pieces(n);
  for (std::size_t i = 0; i < n; ++i) pieces[i].duration = h[i];
  std::vector<double> y(n + 1);
  for (int c = 0; c < 4; ++c) {
    for (std::size_t i = 0; i <= n; ++i) y[i] = c < 3 ? samples[i].position[c] : samples[i].yaw;
    if (c == 3)  // unwrap: each yaw within half a turn of the one before
      for (std::size_t i = 1; i <= n; ++i)
        y[i] -= 2.0 * M_PI * std::round((y[i] - y[i - 1]) / (2.0 * M_PI));
    const std::vector<double> m = secondDerivatives(h, y);
    // On [t_i, t_i+1], u = t - t_i: S = y_i + b u + (M_i / 2) u^2 + (M_i+1 - M_i) / (6 h) u^3,
    // with b = (y_i+1 - y_i) / h - h (2 M_i + M_i+1) / 6 (the slope that makes S(t_i+1) = y_i+1).
    for (std::size_t i = 0; i < n; ++i) {
      ReferencePiece::Coefficients& k = pieces[i].coefficients;
      k(0, c) = y[i];
      k(1, c) = (y[i + 1] - y[i]) / h[i] - h[i] * (2.0 * m[i] + m[i + 1]) / 6.0;
      k(2, c) = 0.5 * m[i];
      k(3, c) = (m[i + 1] - m[i]) / (6.0 * h[i]);
    }
  }
  return pieces;
}

}  // namespace cosim
