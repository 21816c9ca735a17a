// The fits on flight segments: the mass from the hover thrust, the rotor drag from the body
// frame's specific force against the body velocity, and the IMU's noise densities in hover.
#include <cmath>

#include "experiments/identify/flight_signals.h"
#include "experiments/identify/identification.h"
#include "experiments/identify/least_squares.h"

namespace cosim {

namespace {

const char* const kOmega[4] = {"omega1", "omega2", "omega3", "omega4"};

double squaredSpeedSum(const IdentificationLog& log, std::size_t k) {
  double s = 0.0;
  for (const char* c : kOmega) s += log.column(c)[k] * log.column(c)[k];
  return s;
}

IdentifiedValue meanValue(const LinearFit& f, const char* unit, const std::string& method) {
  IdentifiedValue v;
  v.identified = true;
  v.value = f.beta[0];
  v.ci_low = f.beta[0] - f.halfWidth95(0);
  v.ci_high = f.beta[0] + f.halfWidth95(0);
  v.residual = f.residual_rms;
  v.residual_unit = unit;
  v.unit = unit;
  v.samples = f.n;
  v.method = method;
  return v;
}

}  // namespace

void fitHoverMass(const std::vector<IdentificationLog>& logs, const IdentifyOptions& o,
                  IdentificationResult& r) {
  const double k_f = o.thrust_coefficient > 0.0 ? o.thrust_coefficient : r.thrust_coefficient.value;
  if (!(k_f > 0.0)) {
    r.mass.not_why = "needs the thrust constant (a thrust stand log or --thrust-coefficient)";
    return;
  }
  // Newton along the world's z: m (g + a_z) = k_f sum omega_i^2 (R e3).z + F_cable,z, so each
  // sample of steady level flight (hover, or flight at constant height, where a_z stays small
  // and the balance holds whatever the horizontal motion) gives
  // m = (k_f sum omega^2 R33 + F_cable,z) / (g + a_z).
  std::vector<double> m, t;
  for (const auto& log : logs) {
    const std::vector<bool> hover = levelRows(log, o);
    if (std::none_of(hover.begin(), hover.end(), [](bool b) { return b; })) continue;
    const auto a_z = smoothedDerivative(log.t, log.column("vz"), 0.05);
    const auto cable = cablePull(log, o);
    for (std::size_t k = 0; k < log.rows; ++k) {
      if (!hover[k]) continue;
      const double lift = k_f * squaredSpeedSum(log, k) * attitudeAt(log, k)(2, 2);
      m.push_back((lift + cable[k].z()) / (o.gravity + a_z[k]));
      t.push_back(log.t[k]);
    }
  }
  if (m.size() < 10) {
    r.mass.not_why =
        "no steady level flight (vertical speed below --hover-speed for --min-hover "
        "seconds) in a log with t, vz and rpm1..4";
    return;
  }
  const LinearFit f = fitLinear(Eigen::VectorXd::Ones(m.size()),
                                Eigen::Map<const Eigen::VectorXd>(m.data(), m.size()));
  r.mass =
      meanValue(f, "kg", "mean of (k_f sum omega^2 R33 + cable pull) / (g + a_z) in level flight");
  // The thrust constant's own uncertainty scales the mass: relative half-widths in quadrature.
  if (!(o.thrust_coefficient > 0.0) && r.thrust_coefficient.identified) {
    const double rel_kf = (r.thrust_coefficient.ci_high - r.thrust_coefficient.value) / k_f;
    const double rel_m = (r.mass.ci_high - r.mass.value) / r.mass.value;
    const double half = r.mass.value * std::hypot(rel_kf, rel_m);
    r.mass.ci_low = r.mass.value - half;
    r.mass.ci_high = r.mass.value + half;
  }
  FitFigure fig{
      "mass", "Mass from each level-flight sample's thrust", "time (s)", "mass (kg)", t, m, {}};
  fig.fitted.assign(m.size(), f.beta[0]);
  r.figures.push_back(std::move(fig));
}

void fitRotorDrag(const std::vector<IdentificationLog>& logs, const IdentifyOptions& o,
                  IdentificationResult& r) {
  const double mass = o.mass > 0.0 ? o.mass : r.mass.value;
  if (!(mass > 0.0)) {
    r.rotor_drag.not_why = "needs the mass (identified from hover, or --mass)";
    return;
  }
  // The simulator's rotor drag (sim/rotor_aerodynamics.cpp, RotorS / PX4): each rotor adds
  // -omega_i c_d v_perp, so the body's specific force in x, y is a = -c_d sum(omega) v_xy / m
  // (plus the accelerometer's bias, one intercept per axis). The cable's pull is taken off.
  std::vector<double> x, y;
  std::vector<int> axis;
  for (const auto& log : logs) {
    if (log.t.empty() || !log.hasAll({"acc_x", "acc_y", "vx", "vy", "vz"})) continue;
    const std::vector<bool> airborne = airborneRows(log);
    const auto cable = cablePull(log, o);
    for (std::size_t k = 0; k < log.rows; ++k) {
      if (!airborne[k]) continue;
      const Eigen::Matrix3d R = attitudeAt(log, k);
      const Eigen::Vector3d v_body =
          R.transpose() *
          Eigen::Vector3d(log.column("vx")[k], log.column("vy")[k], log.column("vz")[k]);
      const Eigen::Vector3d cable_body = R.transpose() * cable[k] / mass;
      const double sum_omega = rotorSpeedSum(log, k);
      for (int a = 0; a < 2; ++a) {
        x.push_back(-sum_omega * v_body[a] / mass);
        y.push_back(log.column(a == 0 ? "acc_x" : "acc_y")[k] - cable_body[a]);
        axis.push_back(a);
      }
    }
  }
  if (x.size() < 20) {
    r.rotor_drag.not_why = "needs airborne rows with acc_x, acc_y, vx, vy, vz and rpm1..4";
    return;
  }
  Eigen::MatrixXd X(x.size(), 3);
  for (std::size_t k = 0; k < x.size(); ++k)
    X.row(k) << x[k], axis[k] == 0 ? 1.0 : 0.0, axis[k] == 1 ? 1.0 : 0.0;
  const LinearFit f = fitLinear(X, Eigen::Map<const Eigen::VectorXd>(y.data(), y.size()));
  IdentifiedValue& d = r.rotor_drag;
  d.identified = true;
  d.value = f.beta[0];
  d.ci_low = f.beta[0] - f.halfWidth95(0);
  d.ci_high = f.beta[0] + f.halfWidth95(0);
  d.residual = f.residual_rms;
  d.residual_unit = "m/s^2";
  d.unit = "N/(m/s)/(rad/s)";
  d.samples = f.n;
  d.method = "least squares of body specific force x, y on -sum(omega) v_body / m, with biases";
  FitFigure fig{"rotor_drag",
                "Body specific force against the rotor-drag regressor",
                "-sum(omega) v_{body} / m (rad/(kg s) m/s)",
                "specific force less bias (m/s^2)",
                {},
                {},
                {}};
  for (std::size_t k = 0; k < x.size(); ++k) {
    fig.x.push_back(x[k]);
    fig.measured.push_back(y[k] - f.beta[1 + axis[k]]);
    fig.fitted.push_back(f.beta[0] * x[k]);
  }
  r.figures.push_back(std::move(fig));
}

}  // namespace cosim
