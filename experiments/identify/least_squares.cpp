#include "experiments/identify/least_squares.h"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace cosim {

double lagOneAutocorrelation(const Eigen::VectorXd& r) {
  const Eigen::Index n = r.size();
  if (n < 3) return 0.0;
  const double mean = r.mean();
  double num = 0.0, den = 0.0;
  for (Eigen::Index i = 0; i < n; ++i) {
    den += (r[i] - mean) * (r[i] - mean);
    if (i > 0) num += (r[i] - mean) * (r[i - 1] - mean);
  }
  if (!(den > 0.0)) return 0.0;
  return std::clamp(num / den, 0.0, 0.999);
}

double effectiveSamples(std::size_t n, double rho) {
  return std::max(2.0, static_cast<double>(n) * (1.0 - rho) / (1.0 + rho));
}

double studentT975(double dof) {
  const double z = 1.959963984540054;
  const double v = std::max(dof, 1.0);
  const double z3 = z * z * z, z5 = z3 * z * z, z7 = z5 * z * z;
  return z + (z3 + z) / (4.0 * v) + (5.0 * z5 + 16.0 * z3 + 3.0 * z) / (96.0 * v * v) +
         (3.0 * z7 + 19.0 * z5 + 17.0 * z3 - 15.0 * z) / (384.0 * v * v * v);
}

double LinearFit::halfWidth95(int i) const {
  const double dof = n_eff - static_cast<double>(beta.size());
  return studentT975(dof) * std::sqrt(std::max(0.0, covariance(i, i)));
}

LinearFit fitLinear(const Eigen::MatrixXd& X, const Eigen::VectorXd& y) {
  const Eigen::Index n = X.rows(), p = X.cols();
  if (n <= p || y.size() != n) throw std::invalid_argument("fitLinear: needs more samples");
  const Eigen::MatrixXd xtx = X.transpose() * X;
  const Eigen::LDLT<Eigen::MatrixXd> ldlt(xtx);
  if (ldlt.info() != Eigen::Success || !(ldlt.vectorD().minCoeff() > 0.0))
    throw std::invalid_argument("fitLinear: the regressors are not independent");
  LinearFit f;
  f.beta = ldlt.solve(X.transpose() * y);
  f.residuals = y - X * f.beta;
  f.n = static_cast<std::size_t>(n);
  f.ssr = f.residuals.squaredNorm();
  f.residual_rms = std::sqrt(f.ssr / static_cast<double>(n));
  f.n_eff = effectiveSamples(f.n, lagOneAutocorrelation(f.residuals));
  // s^2 (X^T X)^-1 with s^2 = SSR / (n - p), scaled by n / n_eff for the correlation.
  const double s2 = f.ssr / static_cast<double>(n - p);
  const double inflation = static_cast<double>(n) / f.n_eff;
  f.covariance = s2 * inflation * ldlt.solve(Eigen::MatrixXd::Identity(p, p));
  return f;
}

}  // namespace cosim
