#pragma once
// What a scenario's `disturbances:` section asks for (sim/aerodynamics.h applies them; the
// models are in sim/wind.h, sim/rotor_aerodynamics.h, sim/ground_effect.h, sim/downwash.h).
#include <Eigen/Core>

namespace cosim {

struct DisturbanceSettings {
  // Per-rotor drag and rolling moment with the airframe's own coefficients (the model file's
  // rotor_drag_coefficient, rolling_moment_coefficient): the RotorS / PX4 form.
  bool rotor_drag = false;
  // A lumped linear drag at the centre of mass, F = -k (v - wind), N per m/s (`drag: k`); for
  // airframes whose rotor drag is not known, and for scenarios written before rotor_drag.
  double drag_coefficient = 0.0;
  Eigen::Vector3d wind = Eigen::Vector3d::Zero();  // mean wind, m/s (world)
  double gust_sigma = 0.0;                         // m/s, standard deviation of each gust component
  double gust_tau = 2.0;                           // s, gust correlation time
  bool ground_effect = false;                      // per rotor, against the surface below it
  bool downwash = false;                           // the wakes of quadrotors above others
  // Wind acts only through a drag term; without one it would silently do nothing.
  bool hasDrag() const { return rotor_drag || drag_coefficient > 0; }
  bool hasWind() const { return wind.squaredNorm() > 0 || gust_sigma > 0; }
  bool any() const { return hasDrag() || hasWind() || ground_effect || downwash; }

  // The keys (sim/declared_keys.h); wind needs a drag term, checked after them.
  template <class Visitor>
  void declareKeys(Visitor& v) {
    v.boolean("rotor_drag", rotor_drag,
              "per-rotor drag and rolling moment with the model file's coefficients (RotorS)");
    v.number("drag", drag_coefficient, 0.0, 100.0,
             "N per m/s, a lumped linear drag at the centre of mass, F = -k (v - wind)");
    v.vec3("wind", wind, -1e300, 1e300, "m/s, the mean wind (world frame), at most 50 m/s");
    v.number("gust", gust_sigma, 0.0, 50.0, "m/s, standard deviation of each gust component");
    v.number("gust_tau", gust_tau, 0.01, 1000.0, "s, the gusts' correlation time");
    v.boolean("ground_effect", ground_effect, "per rotor, against the surface below it");
    v.boolean("downwash", downwash, "the wakes of quadrotors above others");
  }
};

constexpr double kMaxWindSpeed = 50.0;  // m/s; above it is a units mistake

}  // namespace cosim
