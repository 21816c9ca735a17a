// How the attitude follows the controller's command: per axis, actual(t) = K desired(t - lag)
// + b fitted by least squares for each lag (whole samples up to 0.2 s), the lag with the least
// residual kept (its interval by the profile-likelihood bound, as the motor delay's). K < 1 is
// a vehicle that tilts less than it is told; the lag how late it gets there.
#include <cmath>
#include <limits>

#include "experiments/identify/flight_signals.h"
#include "experiments/identify/identification.h"
#include "experiments/identify/least_squares.h"

// GCC 12 warns -Wrestrict, -Warray-bounds, -Wstringop-overflow inside libstdc++ where a string is
// assigned or concatenated once inlined (GCC bug 105329, a false positive).
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wrestrict"
#pragma GCC diagnostic ignored "-Warray-bounds"
#pragma GCC diagnostic ignored "-Wstringop-overflow"
#endif

namespace cosim {

namespace {

constexpr double kChi2One95 = 3.841458820694124;
constexpr double kMaxLag = 0.2;  // s

struct Pairs {
  std::vector<double> actual, desired, t;
};

Pairs pairs(const std::vector<IdentificationLog>& logs, const char* axis, const char* axis_des,
            std::size_t d, double dt) {
  Pairs p;
  for (const auto& log : logs) {
    if (log.t.empty() || !log.hasAll({axis, axis_des}) ||
        std::abs(log.samplePeriod() - dt) > 0.02 * dt)
      continue;
    const std::vector<bool> airborne = airborneRows(log);
    const bool any_rotor = hasRotorSpeeds(log);
    for (std::size_t k = d; k < log.rows; ++k) {
      if (any_rotor && (!airborne[k] || !airborne[k - d])) continue;
      if (std::abs(log.t[k] - log.t[k - d] - static_cast<double>(d) * dt) > 0.2 * dt) continue;
      p.actual.push_back(log.column(axis)[k]);
      p.desired.push_back(log.column(axis_des)[k - d]);
      p.t.push_back(log.t[k]);
    }
  }
  return p;
}

LinearFit fitPairs(const Pairs& p) {
  Eigen::MatrixXd X(p.actual.size(), 2);
  for (std::size_t k = 0; k < p.actual.size(); ++k) X.row(k) << p.desired[k], 1.0;
  return fitLinear(X, Eigen::Map<const Eigen::VectorXd>(p.actual.data(), p.actual.size()));
}

void fitAxis(const std::vector<IdentificationLog>& logs, const char* axis, const char* axis_des,
             AttitudeTracking& out, IdentificationResult& r) {
  double dt = 0.0;
  for (const auto& log : logs)
    if (!log.t.empty() && log.hasAll({axis, axis_des})) {
      dt = log.samplePeriod();
      break;
    }
  out.gain.not_why = out.lag.not_why =
      std::string("needs a timed log with ") + axis + " and " + axis_des;
  if (!(dt > 0.0)) return;
  const auto max_d = static_cast<std::size_t>(kMaxLag / dt);
  std::vector<double> mse(max_d + 1, std::numeric_limits<double>::infinity());
  std::size_t best = 0;
  for (std::size_t d = 0; d <= max_d; ++d) {
    const Pairs p = pairs(logs, axis, axis_des, d, dt);
    if (p.actual.size() < 20) continue;
    mse[d] = fitPairs(p).ssr / static_cast<double>(p.actual.size());
    if (mse[d] < mse[best]) best = d;
  }
  if (!std::isfinite(mse[best])) return;
  const Pairs p = pairs(logs, axis, axis_des, best, dt);
  const LinearFit f = fitPairs(p);
  const double bound = mse[best] * (1.0 + kChi2One95 / f.n_eff);
  std::size_t lo = best, hi = best;
  while (lo > 0 && mse[lo - 1] <= bound) --lo;
  while (hi < max_d && mse[hi + 1] <= bound) ++hi;
  out.gain.identified = true;
  out.gain.value = f.beta[0];
  out.gain.ci_low = f.beta[0] - f.halfWidth95(0);
  out.gain.ci_high = f.beta[0] + f.halfWidth95(0);
  out.gain.residual = f.residual_rms;
  out.gain.residual_unit = "rad";
  out.gain.unit = "";
  out.gain.samples = f.n;
  out.gain.method = std::string("least squares of ") + axis + " on the lagged " + axis_des;
  out.lag = out.gain;
  out.lag.value = static_cast<double>(best) * dt;
  out.lag.ci_low = std::max(0.0, (static_cast<double>(lo) - 0.5) * dt);
  out.lag.ci_high = (static_cast<double>(hi) + 0.5) * dt;
  out.lag.unit = "s";
  out.lag.method = "search over whole samples for the least residual";
  out.gain.not_why.clear();
  out.lag.not_why.clear();
  FitFigure fig{std::string("attitude_") + axis,
                std::string("Commanded and actual ") + axis,
                "time (s)",
                std::string(axis) + " (rad)",
                {},
                {},
                {}};
  for (std::size_t k = 0; k < p.t.size() && p.t[k] - p.t[0] < 6.0; ++k) {
    if (k > 0 && p.t[k] < p.t[k - 1]) break;
    fig.x.push_back(p.t[k]);
    fig.measured.push_back(p.actual[k]);
    fig.fitted.push_back(f.beta[0] * p.desired[k] + f.beta[1]);
  }
  r.figures.push_back(std::move(fig));
}

}  // namespace

void fitAttitudeTracking(const std::vector<IdentificationLog>& logs, IdentificationResult& r) {
  fitAxis(logs, "roll", "roll_des", r.roll, r);
  fitAxis(logs, "pitch", "pitch_des", r.pitch, r);
}

}  // namespace cosim
