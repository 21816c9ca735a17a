// The motor fits: the steady-state map PWM and battery voltage -> rotor speed, the thrust
// constant, and the motor's pure delay and first-order time constants.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>

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

constexpr double kPwmFullScale = 65535.0;  // the firmware's 16-bit motor PWM
const char* const kPwm[4] = {"pwm1", "pwm2", "pwm3", "pwm4"};
const char* const kOmega[4] = {"omega1", "omega2", "omega3", "omega4"};

bool hasMotorColumns(const IdentificationLog& log) {
  return log.has("vbat") && hasRotorSpeeds(log) && log.hasAll({"pwm1", "pwm2", "pwm3", "pwm4"});
}

// The motor voltage v = duty * V_battery, duty = PWM / 65535.
double motorVoltage(double pwm, double vbat) {
  return pwm / kPwmFullScale * vbat;
}

IdentifiedValue fromFit(const LinearFit& f, int i, const char* unit, const char* method) {
  IdentifiedValue v;
  v.identified = true;
  v.value = f.beta[i];
  v.ci_low = f.beta[i] - f.halfWidth95(i);
  v.ci_high = f.beta[i] + f.halfWidth95(i);
  v.residual = f.residual_rms;
  v.unit = unit;
  v.samples = f.n;
  v.method = method;
  return v;
}

}  // namespace

double steadyRotorSpeed(const IdentificationResult& r, double pwm, double vbat) {
  const double v = motorVoltage(pwm, vbat);
  return r.motor_speed[0].value + r.motor_speed[1].value * v + r.motor_speed[2].value * v * v;
}

namespace {

// The ARX rows of every timed motor log at delay d: X = [omega[k], 1, v, v^2], y = omega[k+1];
// with `fig_v`, every tenth sample's (v, omega) for the figure too.
void arxRows(const std::vector<IdentificationLog>& logs, std::size_t d, Eigen::MatrixXd& X,
             Eigen::VectorXd& y, std::vector<double>* fig_v, std::vector<double>* fig_w) {
  std::vector<std::array<double, 4>> rows;
  for (const auto& log : logs) {
    if (log.t.empty() || !hasMotorColumns(log)) continue;
    const double dt = log.samplePeriod();
    // In flight only: a motor starting on the ground is not yet the first-order lag.
    const std::vector<bool> airborne = airborneRows(log);
    for (int i = 0; i < 4; ++i) {
      const auto& w = log.column(kOmega[i]);
      const auto& pwm = log.column(kPwm[i]);
      for (std::size_t k = d; k + 1 < log.rows; ++k) {
        if (std::abs(log.t[k + 1] - log.t[k] - dt) > 0.2 * dt || !(pwm[k - d] > 0.0) ||
            !(w[k] > 0.0) || !airborne[k] || !airborne[k + 1])
          continue;
        const double v = motorVoltage(pwm[k - d], log.column("vbat")[k - d]);
        rows.push_back({w[k], v, v * v, w[k + 1]});
        if (fig_v && k % 10 == 0) {
          fig_v->push_back(v);
          fig_w->push_back(w[k]);
        }
      }
    }
  }
  X.resize(static_cast<Eigen::Index>(rows.size()), 4);
  y.resize(static_cast<Eigen::Index>(rows.size()));
  for (std::size_t k = 0; k < rows.size(); ++k) {
    X.row(static_cast<Eigen::Index>(k)) << rows[k][0], 1.0, rows[k][1], rows[k][2];
    y[static_cast<Eigen::Index>(k)] = rows[k][3];
  }
}

// A flight's rotor speeds never settle for long: the map is fitted with the motor's lag, a
// first-order ARX model per sample pair (one time constant, delay d samples):
//   omega[k+1] = a omega[k] + b0 + b1 v[k-d] + b2 v[k-d]^2, and omega_ss = b / (1 - a)
// (the lag's fixed point). d is searched up to options.max_motor_delay; the coefficients'
// covariance follows from (a, b) by the delta method.
bool fitFlightMap(const std::vector<IdentificationLog>& logs, const IdentifyOptions& o,
                  IdentificationResult& r, std::vector<double>& fig_v, std::vector<double>& fig_w) {
  double best_mse = std::numeric_limits<double>::infinity();
  LinearFit best;
  std::size_t best_d = 0;
  double dt = 0.0;
  for (const auto& log : logs)
    if (!log.t.empty() && hasMotorColumns(log)) dt = log.samplePeriod();
  if (!(dt > 0.0)) return false;
  const auto max_d = static_cast<std::size_t>(std::floor(o.max_motor_delay / dt + 1e-9));
  for (std::size_t d = 0; d <= max_d; ++d) {
    Eigen::MatrixXd X;
    Eigen::VectorXd y;
    arxRows(logs, d, X, y, nullptr, nullptr);
    if (X.rows() < 50) continue;
    const LinearFit f = fitLinear(X, y);
    if (f.ssr / static_cast<double>(f.n) < best_mse) {
      best_mse = f.ssr / static_cast<double>(f.n);
      best = f;
      best_d = d;
    }
  }
  if (!std::isfinite(best_mse) || !(best.beta[0] < 1.0)) return false;
  Eigen::MatrixXd X;
  Eigen::VectorXd y;
  arxRows(logs, best_d, X, y, &fig_v, &fig_w);
  const double a = best.beta[0], gain = 1.0 - a;
  const char* units[3] = {"rad/s", "rad/s/V", "rad/s/V^2"};
  for (int i = 0; i < 3; ++i) {
    const double b = best.beta[1 + i];
    // c = b / (1 - a): gradient (dc/da, dc/db) = (b / (1 - a)^2, 1 / (1 - a)).
    Eigen::Vector2d grad(b / (gain * gain), 1.0 / gain);
    Eigen::Matrix2d cov;
    cov << best.covariance(0, 0), best.covariance(0, 1 + i), best.covariance(1 + i, 0),
        best.covariance(1 + i, 1 + i);
    const double half = studentT975(best.n_eff - 4.0) * std::sqrt(grad.dot(cov * grad));
    IdentifiedValue& c = r.motor_speed[i];
    c.identified = true;
    c.value = b / gain;
    c.ci_low = c.value - half;
    c.ci_high = c.value + half;
    c.unit = units[i];
    c.samples = best.n;
    c.method =
        "first-order ARX fit of the flight's rotor speeds on v = PWM/65535 V_battery, "
        "omega_ss = b / (1 - a)";
  }
  // The residual of the map itself: the ARX one-step residual is the lag's, not the map's; the
  // map's is the RMS of omega - omega_ss over the samples (it includes the lag's transients).
  double sq = 0.0;
  for (std::size_t k = 0; k < fig_v.size(); ++k) {
    const double e = fig_w[k] - steadyRotorSpeed(r, fig_v[k] * kPwmFullScale, 1.0);
    sq += e * e;
  }
  for (auto& c : r.motor_speed) {
    c.residual = fig_v.empty() ? 0.0 : std::sqrt(sq / static_cast<double>(fig_v.size()));
    c.residual_unit = "rad/s";
  }
  return true;
}

}  // namespace

void fitMotorMap(const std::vector<IdentificationLog>& logs, const IdentifyOptions& o,
                 IdentificationResult& r) {
  using Logs = IdentifyOptions::MotorMapLogs;
  const bool any_flight = std::any_of(
      logs.begin(), logs.end(), [](const auto& l) { return !l.t.empty() && hasMotorColumns(l); });
  std::vector<double> v, w;
  if (o.motor_map_logs == Logs::Flight || (o.motor_map_logs == Logs::Auto && any_flight)) {
    if (!fitFlightMap(logs, o, r, v, w)) {
      for (auto& c : r.motor_speed)
        c.not_why =
            "needs flight logs with t, vbat, pwm1..4 and rpm1..4 whose speeds follow a "
            "first-order lag";
      return;
    }
    FitFigure fig{"motor_map",
                  "Rotor speed against motor voltage (flight samples)",
                  "motor voltage v = PWM/65535 V_{battery} (V)",
                  "rotor speed (rad/s)",
                  v,
                  w,
                  {}};
    for (const double vk : v) fig.fitted.push_back(steadyRotorSpeed(r, vk * kPwmFullScale, 1.0));
    r.figures.push_back(std::move(fig));
    return;
  }
  for (const auto& log : logs) {
    if (!hasMotorColumns(log) || !log.t.empty()) continue;
    for (int i = 0; i < 4; ++i)
      for (std::size_t k = 0; k < log.rows; ++k) {
        const double pwm = log.column(kPwm[i])[k], wk = log.column(kOmega[i])[k];
        if (!(pwm > 0.0) || !(wk > 0.0)) continue;
        v.push_back(motorVoltage(pwm, log.column("vbat")[k]));
        w.push_back(wk);
      }
  }
  if (w.size() < 10) {
    for (auto& c : r.motor_speed)
      c.not_why = "fewer than 10 thrust-stand rows with vbat, pwm and rpm1..4";
    return;
  }
  // omega_ss = c0 + c1 v + c2 v^2: linear in the coefficients, ordinary least squares.
  Eigen::MatrixXd X(w.size(), 3);
  Eigen::VectorXd y(w.size());
  for (std::size_t k = 0; k < w.size(); ++k) {
    X.row(k) << 1.0, v[k], v[k] * v[k];
    y[k] = w[k];
  }
  const LinearFit f = fitLinear(X, y);
  const char* units[3] = {"rad/s", "rad/s/V", "rad/s/V^2"};
  for (int i = 0; i < 3; ++i) {
    r.motor_speed[i] =
        fromFit(f, i, units[i],
                "least squares of the thrust stand's rotor speeds on v = PWM/65535 V_battery");
    r.motor_speed[i].residual_unit = "rad/s";
  }
  FitFigure fig{"motor_map",
                "Thrust-stand rotor speed against motor voltage",
                "motor voltage v = PWM/65535 V_{battery} (V)",
                "rotor speed (rad/s)",
                v,
                w,
                {}};
  for (const double vk : v) fig.fitted.push_back(f.beta[0] + f.beta[1] * vk + f.beta[2] * vk * vk);
  r.figures.push_back(std::move(fig));
}

void fitThrustCoefficient(const std::vector<IdentificationLog>& logs, IdentificationResult& r) {
  std::vector<double> s, thrust;
  for (const auto& log : logs) {
    if (!log.has("thrust") || !hasRotorSpeeds(log)) continue;
    for (std::size_t k = 0; k < log.rows; ++k) {
      double sum = 0.0;
      for (const char* c : kOmega) sum += log.column(c)[k] * log.column(c)[k];
      if (!(sum > 0.0)) continue;
      s.push_back(sum);
      thrust.push_back(log.column("thrust")[k]);
    }
  }
  if (s.size() < 3) {
    r.thrust_coefficient.not_why = "no log with a thrust column beside rpm1..4 (a thrust stand)";
    return;
  }
  // T = k_f sum_i omega_i^2 (each rotor k_f omega^2): through the origin.
  const LinearFit f = fitLinear(Eigen::Map<const Eigen::VectorXd>(s.data(), s.size()),
                                Eigen::Map<const Eigen::VectorXd>(thrust.data(), thrust.size()));
  r.thrust_coefficient =
      fromFit(f, 0, "N/(rad/s)^2", "least squares of measured thrust on sum omega_i^2");
  r.thrust_coefficient.residual_unit = "N";
  FitFigure fig{"thrust",
                "Thrust against the sum of squared rotor speeds",
                "sum of squared rotor speeds ((rad/s)^2)",
                "thrust (N)",
                s,
                thrust,
                {}};
  for (const double x : s) fig.fitted.push_back(f.beta[0] * x);
  r.figures.push_back(std::move(fig));
}

}  // namespace cosim
