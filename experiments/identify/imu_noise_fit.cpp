// The IMU's white-noise densities in hover, vibration included: in each hover run every axis
// less its centred moving mean over 0.1 s (the vehicle's own slow motion) leaves the noise; its
// variance over N-sample means is sigma^2 (1 - 1/N), corrected. The simulator draws each
// sample's noise as density / sqrt(dt) (sim/sensors/imu_sensor.cpp, the Kalibr / RotorS
// convention), so the density is sigma sqrt(dt) at the log's sample period dt. The three axes'
// variances are averaged: sensors.imu has one density per sensor.
#include <algorithm>
#include <cmath>

#include "experiments/identify/flight_signals.h"
#include "experiments/identify/identification.h"
#include "experiments/identify/least_squares.h"

namespace cosim {

namespace {

struct AxisNoise {
  double sum_sq = 0.0;
  std::size_t n = 0;
  std::vector<double> residual;  // in sample order, for its autocorrelation
};

// Adds the detrended hover samples of `column` to `out`.
void addHoverResiduals(const IdentificationLog& log, const std::vector<bool>& hover,
                       const std::string& column, std::size_t half, AxisNoise& out) {
  const auto& x = log.column(column);
  const double corr = 1.0 / (1.0 - 1.0 / static_cast<double>(2 * half + 1));
  for (std::size_t k = half; k + half < log.rows; ++k) {
    if (!hover[k - half] || !hover[k + half]) continue;
    double mean = 0.0;
    for (std::size_t j = k - half; j <= k + half; ++j) mean += x[j];
    mean /= static_cast<double>(2 * half + 1);
    const double e = x[k] - mean;
    out.sum_sq += corr * e * e;
    out.residual.push_back(e);
    ++out.n;
  }
}

IdentifiedValue density(const std::vector<AxisNoise>& axes, double dt, const char* unit,
                        const char* what) {
  IdentifiedValue v;
  double var = 0.0, n_eff = 0.0;
  std::vector<double> per_axis;
  for (const auto& a : axes) {
    const double va = a.sum_sq / static_cast<double>(a.n);
    var += va / static_cast<double>(axes.size());
    per_axis.push_back(std::sqrt(va * dt));
    n_eff += effectiveSamples(a.n, lagOneAutocorrelation(Eigen::Map<const Eigen::VectorXd>(
                                       a.residual.data(), a.residual.size())));
  }
  v.identified = true;
  v.value = std::sqrt(var * dt);
  // A variance over n_eff samples: its relative standard error sqrt(2 / n_eff) (chi-square).
  const double rel = 1.959963984540054 * std::sqrt(2.0 / n_eff);
  v.ci_low = std::sqrt(std::max(0.0, var * (1.0 - rel)) * dt);
  v.ci_high = std::sqrt(var * (1.0 + rel) * dt);
  // The residual: how far the three axes' densities spread about their mean (RMS).
  double spread = 0.0;
  for (const double d : per_axis) spread += (d - v.value) * (d - v.value);
  v.residual = std::sqrt(spread / static_cast<double>(per_axis.size()));
  v.residual_unit = unit;
  v.unit = unit;
  v.samples = axes.front().n;
  v.method = std::string(what) + " in hover less its 0.1 s moving mean; axes " +
             std::to_string(per_axis[0]) + ", " + std::to_string(per_axis[1]) + ", " +
             std::to_string(per_axis[2]);
  return v;
}

}  // namespace

void fitImuNoise(const std::vector<IdentificationLog>& logs, const IdentifyOptions& o,
                 IdentificationResult& r) {
  const std::vector<std::string> gyro{"gyro_x", "gyro_y", "gyro_z"};
  const std::vector<std::string> acc{"acc_x", "acc_y", "acc_z"};
  std::vector<AxisNoise> g(3), a(3);
  double dt = 0.0;
  FitFigure fig{"imu_noise", "Hover gyroscope x less its 0.1 s moving mean",
                "time (s)",  "gyro x residual (rad/s)",
                {},          {},
                {}};
  for (const auto& log : logs) {
    const bool has_g = log.hasAll(gyro), has_a = log.hasAll(acc);
    if (!has_g && !has_a) continue;
    const std::vector<bool> hover = hoverRows(log, o);
    if (std::none_of(hover.begin(), hover.end(), [](bool b) { return b; })) continue;
    const double period = log.samplePeriod();
    if (dt == 0.0) dt = period;
    if (std::abs(period - dt) > 0.02 * dt) continue;  // one sample rate: one density
    const auto half = static_cast<std::size_t>(std::round(0.05 / dt));
    for (int i = 0; i < 3; ++i) {
      if (has_g) addHoverResiduals(log, hover, gyro[i], half, g[i]);
      if (has_a) addHoverResiduals(log, hover, acc[i], half, a[i]);
    }
    if (fig.x.empty() && has_g)
      for (std::size_t k = 0; k < g[0].residual.size() && k < 1000; ++k) {
        fig.x.push_back(static_cast<double>(k) * dt);
        fig.measured.push_back(g[0].residual[k]);
        fig.fitted.push_back(r.gyro_noise.value);
      }
  }
  const auto enough = [](const std::vector<AxisNoise>& axes) {
    return std::all_of(axes.begin(), axes.end(), [](const auto& x) { return x.n >= 100; });
  };
  const char* why =
      "needs 100 or more hover samples (speed below --hover-speed for --min-hover "
      "seconds) in a log with t, vx, vy, vz, rpm1..4 and the IMU's columns";
  if (enough(g))
    r.gyro_noise = density(g, dt, "rad/s/sqrt(Hz)", "gyroscope");
  else
    r.gyro_noise.not_why = why;
  if (enough(a))
    r.accel_noise = density(a, dt, "m/s^2/sqrt(Hz)", "accelerometer");
  else
    r.accel_noise.not_why = why;
  if (!fig.x.empty() && r.gyro_noise.identified) {
    // The band +- one identified sigma per sample (density / sqrt(dt)).
    fig.fitted.assign(fig.x.size(), r.gyro_noise.value / std::sqrt(dt));
    r.figures.push_back(std::move(fig));
  }
}

}  // namespace cosim
