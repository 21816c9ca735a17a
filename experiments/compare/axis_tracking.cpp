#include "experiments/compare/axis_tracking.h"

#include <algorithm>
#include <cmath>

#include "experiments/compare/reference_alignment.h"

namespace cosim {

namespace {

struct AxisSamples {
  std::vector<double> s;
  std::vector<Eigen::Vector3d> r;
};

// Per-axis misfit at lag delta on every stride-th sample (the mean difference removed).
Eigen::Vector3d axisMisfit(const AxisSamples& in, const SampledPath& flight, double delta,
                           std::size_t stride, const StopToken& stop) {
  if (stop.expired()) throw AlignmentInterrupted();
  Eigen::Vector3d sum = Eigen::Vector3d::Zero(), squares = Eigen::Vector3d::Zero();
  double n = 0.0;
  for (std::size_t k = 0; k < in.s.size(); k += stride, n += 1.0) {
    const Eigen::Vector3d diff = flight.at(in.s[k] + delta) - in.r[k];
    sum += diff;
    squares += diff.cwiseProduct(diff);
  }
  const Eigen::Vector3d mean = sum / n;
  return (squares / n - mean.cwiseProduct(mean)).cwiseMax(0.0);
}

// Golden section for one axis on [a, b].
double refineLag(const AxisSamples& in, const SampledPath& flight, int axis, double a, double b,
                 const StopToken& stop) {
  const double ratio = (std::sqrt(5.0) - 1.0) / 2.0;
  const auto j = [&](double delta) { return axisMisfit(in, flight, delta, 1, stop)[axis]; };
  double c = b - ratio * (b - a), d = a + ratio * (b - a), jc = j(c), jd = j(d);
  // (2 steps of 1 ms down to 1e-5 s: 24 golden steps.)
  while (b - a > 1e-5) {
    if (jc <= jd) {
      b = d, d = c, jd = jc;
      c = b - ratio * (b - a);
      jc = j(c);
    } else {
      a = c, c = d, jc = jd;
      d = a + ratio * (b - a);
      jd = j(d);
    }
  }
  return 0.5 * (a + b);
}

double leastSquaresGain(const AxisSamples& in, const SampledPath& flight, int axis, double lag) {
  double mf = 0.0, mr = 0.0;
  const double n = static_cast<double>(in.s.size());
  for (std::size_t k = 0; k < in.s.size(); ++k) {
    mf += flight.at(in.s[k] + lag)[axis] / n;
    mr += in.r[k][axis] / n;
  }
  double cov = 0.0, var = 0.0;
  for (std::size_t k = 0; k < in.s.size(); ++k) {
    const double dr = in.r[k][axis] - mr;
    cov += (flight.at(in.s[k] + lag)[axis] - mf) * dr;
    var += dr * dr;
  }
  return cov / var;
}

}  // namespace

AxisTracking axisTracking(const std::vector<double>& reference_t,
                          const std::vector<Eigen::Vector3d>& reference_p,
                          const SampledPath& flight, const StopToken& stop) {
  AxisTracking out;
  if (flight.size() < 2) return out;
  AxisSamples in;
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d hi = -lo;
  for (std::size_t k = 0; k < reference_t.size(); ++k) {
    const double s = reference_t[k];
    if (s - kMaxAxisLag < flight.start() || s + kMaxAxisLag > flight.end()) continue;
    in.s.push_back(s);
    in.r.push_back(reference_p[k]);
    lo = lo.cwiseMin(reference_p[k]);
    hi = hi.cwiseMax(reference_p[k]);
  }
  if (in.s.size() < kMinAxisSamples) return out;
  const std::size_t stride = std::max<std::size_t>(1, in.s.size() / kCoarseAxisSamples);
  const int steps = static_cast<int>(std::lround(kMaxAxisLag / kAxisLagStep));
  Eigen::Vector3d best_j = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d best_lag = Eigen::Vector3d::Zero();
  for (int i = -steps; i <= steps; ++i) {
    const double delta = i * kAxisLagStep;
    const Eigen::Vector3d j = axisMisfit(in, flight, delta, stride, stop);
    for (int a = 0; a < 3; ++a)
      if (j[a] < best_j[a]) best_j[a] = j[a], best_lag[a] = delta;
  }
  for (int a = 0; a < 3; ++a) {
    if (hi[a] - lo[a] < kStillAxisExtent) continue;
    const double lag = refineLag(in, flight, a, std::max(-kMaxAxisLag, best_lag[a] - kAxisLagStep),
                                 std::min(kMaxAxisLag, best_lag[a] + kAxisLagStep), stop);
    out.lag_s[a] = lag;
    out.amplitude_ratio[a] = leastSquaresGain(in, flight, a, lag);
  }
  return out;
}

}  // namespace cosim
