#pragma once
// The thrust a quadrotor team's trajectories ask of each member, with the downwash of the members
// above it counted: the total thrust m |a + g e_z| of its trajectory (differential flatness,
// Mellinger and Kumar, ICRA 2011, eq. 6) against its rotors' maximum, which the inflow u of the
// wakes from above lowers to 4 T_max (1 - u / v_0) (the axial-inflow law of sim/downwash.h, PX4's
// motor model). Each member above blows the wake of its four rotors, each at its own planned
// thrust, taken as starting at its centre (the rotors' 5 cm offsets neglected: at the 0.6 m or
// more a pair keeps vertically, a rotor's wake is wider than that offset, Pope's spread
// 0.094 dz); the four add by momentum flux, as in sim/downwash.h.
#include <cstddef>
#include <vector>

#include "control/quadrotor_params.h"
#include "planning/trajectory/piecewise_polynomial_trajectory.h"

namespace cosim {

struct TeamThrustPeak {
  double fraction = 0.0;   // the largest planned thrust over the available maximum
  std::size_t member = 0;  // whose
  double t = 0.0;          // s, when
};

// The largest thrust fraction over the members' trajectories, sampled every `dt` s.
// `airframes[i]` is what member i's flight software believes of its airframe.
TeamThrustPeak peakTeamThrust(const std::vector<PiecewisePolynomialTrajectory>& trajectories,
                              const std::vector<QuadrotorParams>& airframes, double dt);

}  // namespace cosim
