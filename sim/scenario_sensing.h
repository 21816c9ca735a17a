#pragma once
// Reading a scenario's `sensors:`, `estimator:` and `model_error:` sections (docs/flight_model.md,
// "Sensors", "Estimator", "Model error"); part of sim/scenario_loader.cpp, kept apart because
// it is one concept: what the flight software knows and believes.
//
//   sensors: {preset: mocap}                  # ideal | mocap | onboard
//   (sim/sensors/sensor_presets.h) sensors: {preset: mocap, position: {noise: 0.002}}      # a
//   preset with some values changed sensors:                                  # explicit blocks
//   (each absent block: no such sensor)
//     imu:      {rate: 500, gyro_noise: 3.4e-4, accel_noise: 4.0e-3, gyro_bias_walk: 3.9e-5,
//                accel_bias_walk: 6.0e-3, gyro_bias_init: 8.7e-3, accel_bias_init: 0.196}
//     position: {rate: 100, noise: 0.001, latency: 0.01}    # metres, seconds
//     attitude: {rate: 100, noise_deg: 0.5, latency: 0.01}
//   estimator: {name: ekf}                    # ekf | ground_truth
//   model_error: {mass: 1.05, inertia: 1.10, thrust_coefficient: 0.95}   # belief / truth
#include <yaml-cpp/yaml.h>

#include "sim/scenario.h"
#include "sim/yaml_reader.h"

namespace cosim {

// Reads the three sections of `root` into `s` (after s.sim and s.vehicles are known: rates are
// checked against the physics rate, latencies against the run's length). An estimator that lacks
// the sensors it needs, or sensing in a scenario without quadrotors, is an error.
void readSensingSections(const YamlReader& r, const YAML::Node& root, Scenario& s);

}  // namespace cosim
