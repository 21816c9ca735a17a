// The motor's dynamics: a pure delay d and a first-order lag, as the simulator's rotor model
// (sim/rotor_model.h, RotorS / PX4's gazebo_motor_model) has them, held over each log sample:
//   omega[k+1] = omega[k] + g (omega_ss(PWM[k - d], V[k - d]) - omega[k]),
//   g = 1 - exp(-dt / tau), tau = tau_up when speeding up, tau_down when slowing down.
// For a given d the gains are linear least squares (two regressors, the error split by its
// sign); d is searched over whole samples and the one with the least squared residual kept.
// Its 95 % interval is the set of delays whose residual is not worse by more than the
// likelihood-ratio bound SSR <= SSR_min (1 + chi2(1, 0.95) / n_eff) (profile likelihood).
#include <algorithm>
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

const char* const kPwm[4] = {"pwm1", "pwm2", "pwm3", "pwm4"};
const char* const kOmega[4] = {"omega1", "omega2", "omega3", "omega4"};
constexpr double kChi2One95 = 3.841458820694124;  // chi-square, 1 dof, 95 %

struct LagRows {
  std::vector<double> up, down, step;  // regressors and the speed change, one row each
  std::vector<double> t, omega, predicted_target;
};

// Every sample pair (k, k+1) of a motor log at the common period dt, delay d samples.
LagRows lagRows(const std::vector<IdentificationLog>& logs, const IdentificationResult& r,
                std::size_t d, double dt) {
  LagRows rows;
  for (const auto& log : logs) {
    if (log.t.empty() || !log.has("vbat") || !hasRotorSpeeds(log) ||
        !log.hasAll({"pwm1", "pwm2", "pwm3", "pwm4"}) ||
        std::abs(log.samplePeriod() - dt) > 0.02 * dt)
      continue;
    const std::vector<bool> airborne = airborneRows(log);
    for (int i = 0; i < 4; ++i) {
      const auto& w = log.column(kOmega[i]);
      const auto& pwm = log.column(kPwm[i]);
      for (std::size_t k = d; k + 1 < log.rows; ++k) {
        // Only evenly spaced stretches, with the motor running.
        if (std::abs(log.t[k + 1] - log.t[k] - dt) > 0.2 * dt ||
            std::abs(log.t[k] - log.t[k - d] - static_cast<double>(d) * dt) > 0.2 * dt)
          continue;
        if (!(pwm[k - d] > 0.0) || !(w[k] > 0.0) || !airborne[k] || !airborne[k + 1]) continue;
        const double target = steadyRotorSpeed(r, pwm[k - d], log.column("vbat")[k - d]);
        const double e = target - w[k];
        rows.up.push_back(e > 0.0 ? e : 0.0);
        rows.down.push_back(e < 0.0 ? e : 0.0);
        rows.step.push_back(w[k + 1] - w[k]);
        rows.t.push_back(log.t[k]);
        rows.omega.push_back(w[k]);
        rows.predicted_target.push_back(target);
      }
    }
  }
  return rows;
}

// Both regressors need rows, or the pair is singular.
bool enoughBothWays(const LagRows& rows) {
  const auto nonzero = [](const std::vector<double>& x) {
    return std::count_if(x.begin(), x.end(), [](double e) { return e != 0.0; });
  };
  return nonzero(rows.up) >= 20 && nonzero(rows.down) >= 20;
}

LinearFit fitGains(const LagRows& rows) {
  Eigen::MatrixXd X(rows.step.size(), 2);
  for (std::size_t k = 0; k < rows.step.size(); ++k) X.row(k) << rows.up[k], rows.down[k];
  return fitLinear(X, Eigen::Map<const Eigen::VectorXd>(rows.step.data(), rows.step.size()));
}

// tau = -dt / ln(1 - g); g's interval maps monotonically (a larger gain is a faster motor).
IdentifiedValue timeConstant(const LinearFit& f, int i, double dt, const char* which) {
  IdentifiedValue v;
  const auto tau = [dt](double g) {
    return g >= 1.0   ? 0.0
           : g <= 0.0 ? std::numeric_limits<double>::infinity()
                      : -dt / std::log(1.0 - g);
  };
  const double g = f.beta[i], h = f.halfWidth95(i);
  if (!(g > 0.0 && g < 1.0)) {
    v.not_why = std::string("the fitted ") + which + " gain " + std::to_string(g) +
                " is outside (0, 1): no first-order lag at this sampling";
    return v;
  }
  v.identified = true;
  v.value = tau(g);
  v.ci_low = tau(g + h);
  v.ci_high = tau(g - h);
  v.residual = f.residual_rms;
  v.residual_unit = "rad/s per sample";
  v.unit = "s";
  v.samples = f.n;
  v.method = std::string("least squares of the speed's step on the ") + which +
             " error to the delayed steady speed";
  return v;
}

}  // namespace

void fitMotorLag(const std::vector<IdentificationLog>& logs, const IdentifyOptions& o,
                 IdentificationResult& r) {
  const char* none = "needs a timed log with vbat, pwm1..4, rpm1..4 and the motor map";
  r.motor_delay.not_why = r.time_constant_up.not_why = r.time_constant_down.not_why = none;
  if (!r.motor_speed[0].identified) return;
  // The motor logs' common sample period (the first one's; others at another rate are left).
  double dt = 0.0;
  for (const auto& log : logs)
    if (!log.t.empty() && log.has("vbat") && hasRotorSpeeds(log) && log.has("pwm1")) {
      dt = log.samplePeriod();
      break;
    }
  if (!(dt > 0.0)) return;
  const auto max_d = static_cast<std::size_t>(std::floor(o.max_motor_delay / dt + 1e-9));
  std::vector<double> ssr(max_d + 1, std::numeric_limits<double>::infinity());
  std::size_t best = 0;
  for (std::size_t d = 0; d <= max_d; ++d) {
    const LagRows rows = lagRows(logs, r, d, dt);
    if (!enoughBothWays(rows)) continue;
    ssr[d] = fitGains(rows).ssr / static_cast<double>(rows.step.size());  // mean: rows differ
    if (ssr[d] < ssr[best]) best = d;
  }
  if (!std::isfinite(ssr[best])) {
    r.motor_delay.not_why = r.time_constant_up.not_why = r.time_constant_down.not_why =
        "fewer than 20 rows each speeding up and slowing down towards the motor map's speed";
    return;
  }
  const LagRows rows = lagRows(logs, r, best, dt);
  const LinearFit f = fitGains(rows);
  const double bound = ssr[best] * (1.0 + kChi2One95 / f.n_eff);
  std::size_t lo = best, hi = best;
  while (lo > 0 && ssr[lo - 1] <= bound) --lo;
  while (hi < max_d && ssr[hi + 1] <= bound) ++hi;
  IdentifiedValue& delay = r.motor_delay;
  delay.identified = true;
  delay.value = static_cast<double>(best) * dt;
  // A whole-sample search: the interval is widened by half a sample each way.
  delay.ci_low = std::max(0.0, (static_cast<double>(lo) - 0.5) * dt);
  delay.ci_high = (static_cast<double>(hi) + 0.5) * dt;
  delay.residual = f.residual_rms;
  delay.residual_unit = "rad/s per sample";
  delay.unit = "s";
  delay.samples = f.n;
  delay.method = "search over whole samples (" + std::to_string(dt * 1e3).substr(0, 5) +
                 " ms) for the least residual of the first-order fit";
  delay.not_why.clear();
  r.time_constant_up = timeConstant(f, 0, dt, "speed-up");
  r.time_constant_down = timeConstant(f, 1, dt, "slow-down");
  // The figure: the identified motor run open loop from the delayed commands over the first
  // 1.5 s of rotor 1's samples, beside the measured speed.
  FitFigure fig{"motor_lag", "Measured rotor speed and the identified motor driven by the PWM",
                "time (s)",  "rotor speed (rad/s)",
                {},          {},
                {}};
  double simulated = rows.omega.empty() ? 0.0 : rows.omega[0];
  for (std::size_t k = 0; k + 1 < rows.step.size() && rows.t[k] - rows.t[0] < 1.5; ++k) {
    if (k > 0 && rows.t[k] < rows.t[k - 1]) break;
    const double e = rows.predicted_target[k] - simulated;
    simulated += (e > 0.0 ? f.beta[0] : f.beta[1]) * e;
    fig.x.push_back(rows.t[k] + dt);
    fig.measured.push_back(rows.omega[k] + rows.step[k]);
    fig.fitted.push_back(simulated);
  }
  r.figures.push_back(std::move(fig));
}

}  // namespace cosim
