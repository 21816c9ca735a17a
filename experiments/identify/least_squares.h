#pragma once
// Ordinary least squares with the parameters' covariance, for system identification
// (experiments/identify/). Samples of a log are correlated in time: the covariance is inflated
// by n / n_eff, with n_eff the effective sample size of AR(1) residuals (Bartlett 1946;
// H. von Storch and F. W. Zwiers, "Statistical Analysis in Climate Research", 1999, eq. 17.5:
// n_eff = n (1 - rho) / (1 + rho), rho the lag-1 autocorrelation of the residuals in sample
// order). Without it the 95 % intervals of a 500 Hz log would be far too narrow.
#include <Eigen/Core>
#include <cstddef>

namespace cosim {

struct LinearFit {
  Eigen::VectorXd beta;        // the parameters
  Eigen::MatrixXd covariance;  // of beta, inflated for correlated residuals
  Eigen::VectorXd residuals;   // y - X beta, in sample order
  double residual_rms = 0.0;
  double ssr = 0.0;    // sum of squared residuals
  std::size_t n = 0;   // samples
  double n_eff = 0.0;  // effective samples (AR(1) of the residuals)
  // The 95 % confidence interval of beta[i]: beta[i] -+ t(0.975, n_eff - p) sqrt(cov(i, i)).
  double halfWidth95(int i) const;
};

// Solves min |y - X beta|^2 (X: n x p, n > p, full column rank; std::invalid_argument otherwise).
LinearFit fitLinear(const Eigen::MatrixXd& X, const Eigen::VectorXd& y);

// The lag-1 autocorrelation of `r` (0 for fewer than 3 samples), clamped to [0, 0.999]: a
// negative one would shrink the intervals below the independent case.
double lagOneAutocorrelation(const Eigen::VectorXd& r);
// n (1 - rho) / (1 + rho), at least 2.
double effectiveSamples(std::size_t n, double rho);

// Student's t 97.5 % quantile for `dof` degrees of freedom (Abramowitz and Stegun 26.7.5, the
// Cornish-Fisher expansion about the normal quantile 1.959964; within 0.2 % from 3 dof up).
double studentT975(double dof);

}  // namespace cosim
