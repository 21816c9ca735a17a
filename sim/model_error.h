#pragma once
// `model_error:` of a scenario: how far the flight software's idea of the airframe is from the
// airframe the physics simulates. Each factor is belief / truth (1 = exact): the controller, the
// trajectory's thrust limit and the conversion of commanded thrust into rotor speed use the
// believed airframe, the physics the true one. A thrust_coefficient of 0.95 means the software
// under-rates its rotors by 5 %: it commands w = sqrt(T / (0.95 k_f)) and gets T / 0.95.
#include "control/quadrotor_params.h"

namespace cosim {

struct ModelError {
  double mass = 1.0;
  double inertia = 1.0;
  double thrust_coefficient = 1.0;
  bool none() const { return mass == 1.0 && inertia == 1.0 && thrust_coefficient == 1.0; }

  // The keys (sim/declared_keys.h). Beliefs off by more than a factor of two are not a model
  // error but a different vehicle.
  template <class Visitor>
  void declareKeys(Visitor& v) {
    v.number("mass", mass, 0.5, 2.0, "the controller's mass / the true mass");
    v.number("inertia", inertia, 0.5, 2.0, "the controller's inertia / the true inertia");
    v.number("thrust_coefficient", thrust_coefficient, 0.5, 2.0,
             "the controller's rotor thrust coefficient k_f / the true one");
  }
};

// The true airframe with mass, inertia and k_f (hence the thrust limits) scaled by `error`.
QuadrotorParams believedAirframe(const QuadrotorParams& truth, const ModelError& error);

}  // namespace cosim
