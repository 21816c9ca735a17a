#pragma once
// Downwash between vehicles: the wake of every rotor of a vehicle above blows down onto the
// rotors of a vehicle below it, which then meet an axial inflow from above and, at the same
// speed, make less thrust.
//
// The wake of one rotor (thrust T, radius R) is taken as a round turbulent jet along the world's
// -z axis from the rotor disc:
// - its exit is the fully contracted slipstream of momentum theory: velocity u_J = 2 v_i with
//   v_i = sqrt(T / (2 rho A)), diameter D_w = 2R / sqrt(2) (half the disc area) (J. G. Leishman,
//   "Principles of Helicopter Aerodynamics", 2nd ed., 2006, Sec. 2.2, eqs. 2.14-2.22);
// - below it, the self-similar far field of a round jet: centreline velocity
//   u_c = u_J min(1, B D_w / dz) and a Gaussian profile u = u_c exp(-ln 2 (r / r_half)^2) with
//   half-width r_half = max(0.59 D_w, S dz), B = 5.8 and S = 0.094 (S. B. Pope, "Turbulent
//   Flows", 2000, Sec. 5.1 and Table 5.1, from the LDA measurements of Hussein, Capp and George
//   1994). 0.59 D_w = sqrt(ln 2 / 2) D_w gives the near-field Gaussian the slipstream's momentum
//   flux (the rotor's thrust); both laws change over near dz = 6 D_w, the end of the potential
//   core. Far below, Pope's B and S with a Gaussian keep 86 % of that flux.
// Wakes of several rotors add by momentum flux (u = sqrt(sum u_k^2)): the four jets of a vehicle
// merge far below into one of four times the momentum flux.
// The lower rotor's thrust at constant speed then falls linearly with the inflow,
// T = k_f w^2 (1 - u / v_0), the axial-airspeed law of PX4's motor model
// (gazebo_motor_model.cpp) with the airframe's zero-thrust inflow v_0 (its maxRelativeAirspeed).
// Simplifications, said plainly: the jet is not advected by the relative motion of the two
// vehicles nor tilted with the upper vehicle, swirl and tip vortices are ignored, and only the
// thrust of the lower rotors is changed (no force on the lower vehicle's body).
// gym-pybullet-drones (Panerati et al. 2021, BaseAviary._downwash) applies an empirical force
// fitted to Crazyflies only; this model scales with every airframe's thrust and rotor size.
#include <Eigen/Core>
#include <vector>

namespace cosim {

constexpr double kAirDensity = 1.225;  // kg/m^3, ISA sea level

// Velocity of one rotor's wake a height dz below the rotor and r off its axis, m/s (0 for dz <= 0).
double rotorWakeVelocity(double thrust, double propeller_radius, double dz, double r);

// One rotor as the downwash sees it: where its hub is (world), which vehicle it belongs to, its
// radius and its thrust.
struct WakeSource {
  Eigen::Vector3d hub = Eigen::Vector3d::Zero();
  int vehicle = 0;
  double radius = 0.0;
  double thrust = 0.0;
};

// Axial inflow from above at each rotor (same order as `rotors`) from the wakes of the other
// vehicles' rotors, m/s.
std::vector<double> downwashInflow(const std::vector<WakeSource>& rotors);

}  // namespace cosim
