#include "run/team_thrust.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include "sim/downwash.h"

namespace cosim {

namespace {

// Members further apart horizontally than this blow no wake worth counting onto each other: the
// Gaussian's half-width is at most 0.094 x 3 m = 0.28 m in a room 3 m high (Pope's spread, as in
// sim/downwash.cpp), and 4 half-widths off the axis the wake is below 1e-4 of its centre.
constexpr double kWakeReach = 1.2;  // m

struct MemberAt {
  Eigen::Vector3d pos;
  double thrust = 0.0;  // N, the member's total planned thrust
};

}  // namespace

TeamThrustPeak peakTeamThrust(const std::vector<PiecewisePolynomialTrajectory>& trajectories,
                              const std::vector<QuadrotorParams>& airframes, double dt) {
  TeamThrustPeak peak;
  double end = 0.0;
  for (const auto& t : trajectories) end = std::max(end, t.duration());
  const std::size_t n = trajectories.size();
  std::vector<MemberAt> at(n);
  for (double t = 0.0; t <= end + 1e-9; t += dt) {
    // Members by horizontal cell of kWakeReach: a member's wake reaches the 3 x 3 cells around.
    std::map<std::pair<long, long>, std::vector<std::size_t>> cells;
    for (std::size_t i = 0; i < n; ++i) {
      const TrajectorySample s = trajectories[i].sample(std::min(t, trajectories[i].duration()));
      const QuadrotorParams& q = airframes[i];
      at[i].pos = s.position;
      at[i].thrust = q.mass * (s.acceleration + Eigen::Vector3d(0, 0, q.gravity)).norm();
      cells[{static_cast<long>(std::floor(s.position.x() / kWakeReach)),
             static_cast<long>(std::floor(s.position.y() / kWakeReach))}]
          .push_back(i);
    }
    for (const auto& [cell, members] : cells)
      for (const std::size_t i : members) {
        double flux = 0.0;  // sum of u^2 over the wakes from above
        for (long dx = -1; dx <= 1; ++dx)
          for (long dy = -1; dy <= 1; ++dy) {
            const auto it = cells.find({cell.first + dx, cell.second + dy});
            if (it == cells.end()) continue;
            for (const std::size_t j : it->second) {
              if (j == i) continue;
              const double dz = at[j].pos.z() - at[i].pos.z();
              const double r = (at[j].pos - at[i].pos).head<2>().norm();
              const double u =
                  rotorWakeVelocity(0.25 * at[j].thrust, airframes[j].propeller_radius, dz, r);
              flux += 4.0 * u * u;  // four rotors' wakes
            }
          }
        const QuadrotorParams& q = airframes[i];
        const double loss = std::min(1.0, std::sqrt(flux) / q.zero_thrust_inflow);
        const double available = 4.0 * q.max_thrust * (1.0 - loss);
        const double fraction = available > 0.0 ? at[i].thrust / available : 1e9;
        if (fraction > peak.fraction) peak = {fraction, i, t};
      }
  }
  return peak;
}

}  // namespace cosim
