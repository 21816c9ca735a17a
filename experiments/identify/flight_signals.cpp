#include "experiments/identify/flight_signals.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace cosim {

bool hasRotorSpeeds(const IdentificationLog& log) {
  return log.hasAll({"omega1", "omega2", "omega3", "omega4"});
}

double rotorSpeedSum(const IdentificationLog& log, std::size_t k) {
  return log.column("omega1")[k] + log.column("omega2")[k] + log.column("omega3")[k] +
         log.column("omega4")[k];
}

std::vector<bool> airborneRows(const IdentificationLog& log) {
  std::vector<bool> out(log.rows, false);
  if (!hasRotorSpeeds(log)) return out;
  std::vector<double> flown;
  for (std::size_t k = 0; k < log.rows; ++k)
    if (rotorSpeedSum(log, k) > 0.0) flown.push_back(rotorSpeedSum(log, k) / 4.0);
  if (flown.empty()) return out;
  std::nth_element(flown.begin(), flown.begin() + flown.size() / 2, flown.end());
  const double floor = 0.6 * flown[flown.size() / 2];
  // A rotor reading far from the others (an rpm sensor that counts half its pulses, as motor 3
  // of some of IMRCLab's payload flights) makes the row unusable: every rotor lifts about a
  // quarter of the weight in flight, so each stays within 35 % of the four's mean.
  for (std::size_t k = 0; k < log.rows; ++k) {
    const double mean = rotorSpeedSum(log, k) / 4.0;
    bool all = true;
    for (const char* c : {"omega1", "omega2", "omega3", "omega4"})
      all = all && log.column(c)[k] >= floor && std::abs(log.column(c)[k] - mean) <= 0.35 * mean;
    out[k] = all;
  }
  return out;
}

namespace {

// Runs of rows where `still` holds for at least min_s, their first and last 0.1 s dropped (the
// vehicle settling).
template <class Still>
std::vector<bool> steadyRuns(const IdentificationLog& log, double min_s, Still still) {
  std::vector<bool> out(log.rows, false);
  const double trim = 0.1;
  std::size_t k = 0;
  while (k < log.rows) {
    if (!still(k)) {
      ++k;
      continue;
    }
    std::size_t end = k;
    while (end < log.rows && still(end)) ++end;
    if (log.t[end - 1] - log.t[k] >= min_s)
      for (std::size_t i = k; i < end; ++i)
        out[i] = log.t[i] - log.t[k] >= trim && log.t[end - 1] - log.t[i] >= trim;
    k = end;
  }
  return out;
}

}  // namespace

std::vector<bool> hoverRows(const IdentificationLog& log, const IdentifyOptions& o) {
  if (log.t.empty() || !log.hasAll({"vx", "vy", "vz"}) || !hasRotorSpeeds(log))
    return std::vector<bool>(log.rows, false);
  const std::vector<bool> airborne = airborneRows(log);
  const auto& vx = log.column("vx");
  const auto& vy = log.column("vy");
  const auto& vz = log.column("vz");
  return steadyRuns(log, o.min_hover_s, [&](std::size_t i) {
    return airborne[i] && std::hypot(vx[i], vy[i], vz[i]) < o.hover_speed;
  });
}

std::vector<bool> levelRows(const IdentificationLog& log, const IdentifyOptions& o) {
  if (log.t.empty() || !log.has("vz") || !hasRotorSpeeds(log))
    return std::vector<bool>(log.rows, false);
  const std::vector<bool> airborne = airborneRows(log);
  const auto& vz = log.column("vz");
  return steadyRuns(log, o.min_hover_s,
                    [&](std::size_t i) { return airborne[i] && std::abs(vz[i]) < o.hover_speed; });
}

Eigen::Matrix3d attitudeAt(const IdentificationLog& log, std::size_t k) {
  if (!log.hasAll({"qw", "qx", "qy", "qz"})) return Eigen::Matrix3d::Identity();
  Eigen::Quaterniond q(log.column("qw")[k], log.column("qx")[k], log.column("qy")[k],
                       log.column("qz")[k]);
  if (!(q.norm() > 0.5)) return Eigen::Matrix3d::Identity();
  return q.normalized().toRotationMatrix();
}

std::vector<double> smoothedDerivative(const std::vector<double>& t, const std::vector<double>& x,
                                       double half_window_s) {
  std::vector<double> out(x.size(), 0.0);
  std::size_t lo = 0, hi = 0;
  for (std::size_t k = 0; k < x.size(); ++k) {
    while (t[k] - t[lo] > half_window_s) ++lo;
    while (hi + 1 < x.size() && t[hi + 1] - t[k] <= half_window_s) ++hi;
    if (hi < k) hi = k;
    if (hi > lo) out[k] = (x[hi] - x[lo]) / (t[hi] - t[lo]);
  }
  return out;
}

std::vector<Eigen::Vector3d> cablePull(const IdentificationLog& log, const IdentifyOptions& o) {
  std::vector<Eigen::Vector3d> out(log.rows, Eigen::Vector3d::Zero());
  if (!(o.payload_mass > 0.0)) return out;
  const Eigen::Vector3d gravity(0.0, 0.0, o.gravity);
  if (log.t.empty() || !log.hasAll({"payload_vx", "payload_vy", "payload_vz"})) {
    for (auto& f : out) f = -o.payload_mass * gravity;
    return out;
  }
  // The payload's acceleration over +-25 ms: its velocity estimate is differentiated.
  const double half = 0.025;
  const auto ax = smoothedDerivative(log.t, log.column("payload_vx"), half);
  const auto ay = smoothedDerivative(log.t, log.column("payload_vy"), half);
  const auto az = smoothedDerivative(log.t, log.column("payload_vz"), half);
  for (std::size_t k = 0; k < log.rows; ++k)
    out[k] = -o.payload_mass * (Eigen::Vector3d(ax[k], ay[k], az[k]) + gravity);
  return out;
}

}  // namespace cosim
