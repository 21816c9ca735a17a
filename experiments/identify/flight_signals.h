#pragma once
// Signals derived from a flight log for the fits: hover segments, the attitude, body-frame
// velocity, smoothed time derivatives and a cable-suspended payload's pull on the vehicle.
#include <Eigen/Core>
#include <vector>

#include "experiments/identify/identification.h"

namespace cosim {

// Whether the log has omega1..4.
bool hasRotorSpeeds(const IdentificationLog& log);
// Sum of the four rotor speeds at row k, rad/s.
double rotorSpeedSum(const IdentificationLog& log, std::size_t k);
// Rows where every rotor turns at least 60 % of the median of the flown rows' mean speed (the
// vehicle is airborne: a landed vehicle's motors idle or stop) and within 35 % of the four's
// mean (no rotor speed misread). All false without omega1..4.
std::vector<bool> airborneRows(const IdentificationLog& log);
// Rows of steady hover: airborne and the speed |v| below options.hover_speed over a run of at
// least options.min_hover_s (its first and last 0.1 s dropped). Needs t, vx, vy, vz, omega1..4.
std::vector<bool> hoverRows(const IdentificationLog& log, const IdentifyOptions& options);
// Rows of steady level flight: airborne with the vertical speed |vz| below options.hover_speed
// over a run of at least options.min_hover_s (ends trimmed as hoverRows). The vertical force
// balance holds there whatever the horizontal motion. Needs t, vz, omega1..4.
std::vector<bool> levelRows(const IdentificationLog& log, const IdentifyOptions& options);
// Body to world rotation at row k from qw, qx, qy, qz (normalised); identity without them.
Eigen::Matrix3d attitudeAt(const IdentificationLog& log, std::size_t k);
// dx/dt by the central difference over +-half_window_s (one-sided at the ends).
std::vector<double> smoothedDerivative(const std::vector<double>& t, const std::vector<double>& x,
                                       double half_window_s);
// The world-frame force a cable-suspended payload of mass m_p pulls the vehicle with: the cable
// holds the payload, so it pulls the vehicle by -m_p (a_p + g e3) (Newton's second law on the
// payload, the cable massless and taut); a_p from the payload's velocity. Zero rows when
// options.payload_mass is 0. A log without payload velocity with a payload mass: the payload
// is taken at rest below the vehicle (-m_p g e3).
std::vector<Eigen::Vector3d> cablePull(const IdentificationLog& log, const IdentifyOptions& o);

}  // namespace cosim
