#pragma once
// Ground effect per rotor: a rotor whose wake meets a surface a height z below it makes more
// thrust at the same speed, T / T_inf = 1 / (1 - (R / 4z)^2) (I. C. Cheeseman and W. E. Bennett,
// "The effect of the ground on a helicopter rotor in forward flight", ARC R&M 3021, 1955, from
// the method of images), R the propeller radius. The surface is whatever lies under that rotor
// along its axis (a ray cast against every geom but the vehicle's own): the floor, an obstacle's
// top, another vehicle. So a quadrotor half over a table edge feels it on two rotors only, and
// rolls. The formula diverges at z = R/4; it is held at its value for z = R/2 (gain 4/3), below
// which the rotor is practically touching.
#include <mujoco/mujoco.h>

#include <Eigen/Core>

namespace cosim {

// 1 / (1 - (R / 4z)^2) for z >= R/2; its value at R/2 below that; 1 with no surface (z < 0 as
// "none found").
double groundEffectFactor(double propeller_radius, double height);

// Distance from `rotor` along -`axis` (world frame, unit) to the nearest geom not belonging to
// `vehicle_body`, or -1 if the ray meets nothing within `range`.
double surfaceDistanceBelow(const mjModel* m, const mjData* d, const Eigen::Vector3d& rotor,
                            const Eigen::Vector3d& axis, int vehicle_body, double range);

}  // namespace cosim
