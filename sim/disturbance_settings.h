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
};

}  // namespace cosim
