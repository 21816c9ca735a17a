#include "experiments/bench/trajectory_generation.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <random>
#include <string>

#include "control/cascade_controller.h"
#include "control/geometric_controller.h"
#include "planning/trajectory/minimum_snap_trajectory.h"

namespace cosim::bench {
namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

// A random walk of n waypoints, 1 to 4 m apart, turning by up to 90 degrees: the shape of a
// thinned any-angle path through clutter. Fixed seed: the same paths every run.
Path randomWalk(int n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> step(1.0, 4.0), turn(-M_PI / 2, M_PI / 2),
      climb(-0.3, 0.3);
  Path path;
  Eigen::Vector3d p(0, 0, 2);
  double heading = 0.0;
  for (int i = 0; i < n; ++i) {
    path.waypoints.push_back(p);
    heading += turn(rng);
    const double d = step(rng);
    p += Eigen::Vector3d(d * std::cos(heading), d * std::sin(heading), d * climb(rng));
  }
  return path;
}

// The median wall time of `repeats` fits, and the last result.
double medianFitMs(const MinimumSnapTrajectory& generator, const Path& path, int repeats,
                   MinimumSnapResult* last) {
  std::vector<double> ms;
  for (int r = 0; r < repeats; ++r) {
    const auto t0 = Clock::now();
    *last = generator.fit(path);
    ms.push_back(msSince(t0));
  }
  std::nth_element(ms.begin(), ms.begin() + ms.size() / 2, ms.end());
  return ms[ms.size() / 2];
}

// Nanoseconds per update over a hover-ish flight with a slowly varying state and reference.
double nsPerUpdate(FlightController& controller, int steps) {
  VehicleState s;
  FlatReference ref;
  double checksum = 0.0;
  const auto t0 = Clock::now();
  for (int k = 0; k < steps; ++k) {
    const double t = k * 0.002;
    s.position = Eigen::Vector3d(0.1 * std::sin(t), 0.1 * std::cos(t), 2.0);
    s.velocity = Eigen::Vector3d(0.1 * std::cos(t), -0.1 * std::sin(t), 0.0);
    s.attitude =
        Eigen::Quaterniond(Eigen::AngleAxisd(0.1 * std::sin(3 * t), Eigen::Vector3d::UnitX()));
    s.angular_velocity = Eigen::Vector3d(0.3 * std::cos(3 * t), 0.0, 0.0);
    ref.position = Eigen::Vector3d(0, 0, 2);
    ref.jerk = Eigen::Vector3d(0.2 * std::sin(t), 0.0, 0.0);
    checksum += controller.update(s, ref, 0.002).rotor_thrusts.sum();
  }
  const double ns = 1e6 * msSince(t0) / steps;
  volatile double sink = checksum;  // keeps the calls from being optimised away
  (void)sink;
  return ns;
}

}  // namespace

Section benchTrajectoryGeneration(bool quick) {
  Section out;
  out.name = "trajectory_generation";
  const int repeats = quick ? 1 : 9;

  MinimumSnapOptions optimised;  // defaults: 3 m/s, 5 m/s^2
  optimised.limits.max_thrust_accel = 2.0 * 9.81;
  MinimumSnapOptions proportional = optimised;
  proportional.optimize_times = false;
  const MinimumSnapTrajectory with_allocation(optimised), closed_form(proportional);

  double ms50 = 0.0;
  for (const int n : {10, 50, 200}) {
    const Path path = randomWalk(n, 1000 + n);
    MinimumSnapResult a, b;
    const double ms_opt = medianFitMs(with_allocation, path, repeats, &a);
    const double ms_cf = medianFitMs(closed_form, path, repeats, &b);
    if (n == 50) ms50 = ms_opt;
    const std::string k = "wp" + std::to_string(n) + "_";
    out.figures.push_back({k + "optimised_ms", ms_opt, "ms"});
    out.figures.push_back({k + "closed_form_ms", ms_cf, "ms"});
    out.figures.push_back({k + "allocation_cost_ratio", ms_opt / ms_cf, "x"});
    out.figures.push_back({k + "nlopt_evaluations", a.counters.at("cost_evaluations"), ""});
    // Both meet the same limits, one of them exactly: the shorter flight is the better allocation.
    out.figures.push_back({k + "flight_time_ratio_optimised_to_proportional",
                           a.trajectory.duration() / b.trajectory.duration(), "x"});
  }

  QuadrotorParams params;
  params.rotor_xy = QuadrotorParams::xLayout(0.225);
  GeometricController geometric(params);
  CascadeController cascade(params, CascadeGains{});
  const int steps = quick ? 20000 : 2000000;
  nsPerUpdate(geometric, steps / 10);  // warm-up
  const double ns_geo = nsPerUpdate(geometric, steps);
  const double ns_cas = nsPerUpdate(cascade, steps);
  out.figures.push_back({"geometric_ns_per_step", ns_geo, "ns"});
  out.figures.push_back({"cascade_ns_per_step", ns_cas, "ns"});
  out.figures.push_back({"geometric_to_cascade_ratio", ns_geo / ns_cas, "x"});

  out.note =
      "minimum snap with NLopt time allocation vs closed form with distance-proportional "
      "times (random-walk paths); geometric vs cascade controller per step. Target 50 "
      "waypoints < 50 ms: " +
      std::string(ms50 < 50.0 ? "met" : "NOT met");
  return out;
}

}  // namespace cosim::bench
