#pragma once
// A small mixed run for the record's tests: a robot creeps 0.4 m while a cf2 crosses 0.5 m above
// it on a minimum-snap trajectory (the robot is measured against its timed plan, the quadrotor
// against its trajectory).
#include <string>

namespace cosim::test {

inline const std::string kRobotAndUavScenario =
    "world:\n  bounds: {min: [0, 0, 0], max: [4, 3, 2]}\nvehicles:\n"
    "  - {name: r0, model: omni_base, start: [2.0, 1.3, 0], goal: [2.0, 1.7, 0]}\n"
    "  - {name: uav1, model: cf2, start: [0.5, 1.5, 0.5], goal: [3.5, 1.5, 0.5]}\n"
    "aerial:\n  trajectory: {mode: minimum_snap, max_speed: 1.0}\n"
    "sim: {timestep: 0.002, control_rate: 250, max_time: 10}\n";

}  // namespace cosim::test
