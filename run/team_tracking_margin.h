#pragma once
// The separation a quadrotor team's plan keeps, grown by the flight controller's tracking error:
// a plan keeps every pair `s` separation ellipsoids apart (planning/team/), and in flight a pair
// comes closer than planned by up to `d` ellipsoids (both vehicles' tracking errors, the downwash
// of vehicles above included), so a plan with s >= 1 + d flies without entering the ellipsoid
// (sim/uav_separation_metrics.h counts each entry as a downwash violation).
//
// d is declared per controller (ControllerEntry::team_shortfall, control/controller_registry.h),
// measured with this simulator: the largest shortfall of the flown closest approach below the
// planned 1.5 ellipsoids over the bundled teams
// (experiments/scenarios/swarm32.yaml: 3D grid, vehicles passing under each other;
// swarm32_dense.yaml: 0.5 m spacing in one plane), downwash on, default gains. The plan keeps
// 1 + 1.25 d (a quarter of the measured shortfall again in reserve), and never less than
// planner.min_separation.
#include <string>

namespace cosim {

// The declared shortfall d of a controller (ellipsoids); for a name not measured, the largest.
double teamPairDeviation(const std::string& controller);

// max(min_separation, 1 + 1.25 teamPairDeviation(controller)).
double teamSeparationFor(const std::string& controller, double min_separation);

}  // namespace cosim
