#include "sim/downwash.h"

#include <algorithm>
#include <cmath>

namespace cosim {

namespace {
constexpr double kJetDecayB = 5.8;     // Pope 2000, Table 5.1 (Hussein et al. 1994, LDA)
constexpr double kJetSpreadS = 0.094;  // same
// Near the rotor the Gaussian's half-width is the one whose momentum flux equals the uniform
// slipstream's (rho u_J^2 pi D_w^2 / 4 = rho u_J^2 pi r_half^2 / (2 ln 2)): the rotor's thrust.
const double kCoreHalfWidth = std::sqrt(std::log(2.0) / 2.0);
}  // namespace

double rotorWakeVelocity(double thrust, double R, double dz, double r) {
  if (dz <= 0.0 || thrust <= 0.0) return 0.0;
  const double area = M_PI * R * R;
  const double v_i = std::sqrt(thrust / (2.0 * kAirDensity * area));
  const double u_jet = 2.0 * v_i;
  const double d_wake = 2.0 * R / std::sqrt(2.0);
  const double u_c = u_jet * std::min(1.0, kJetDecayB * d_wake / dz);
  const double r_half = std::max(kCoreHalfWidth * d_wake, kJetSpreadS * dz);
  return u_c * std::exp(-std::log(2.0) * (r / r_half) * (r / r_half));
}

std::vector<double> downwashInflow(const std::vector<WakeSource>& rotors) {
  std::vector<double> inflow(rotors.size(), 0.0);
  for (std::size_t j = 0; j < rotors.size(); ++j) {
    double flux = 0.0;  // sum of u^2 (momentum flux per unit area, over rho)
    for (const WakeSource& i : rotors) {
      if (i.vehicle == rotors[j].vehicle) continue;
      const double dz = i.hub.z() - rotors[j].hub.z();
      if (dz <= 0.0) continue;
      const double r = (i.hub - rotors[j].hub).head<2>().norm();
      // Beyond 4 half-widths the Gaussian is below 1e-4 of its centre: skip the exp.
      if (r > 4.0 * std::max(i.radius, kJetSpreadS * dz) + i.radius) continue;
      const double u = rotorWakeVelocity(i.thrust, i.radius, dz, r);
      flux += u * u;
    }
    inflow[j] = std::sqrt(flux);
  }
  return inflow;
}

}  // namespace cosim
