#pragma once
// The named sensor suites of a scenario's `sensors: {preset: NAME}` (docs/flight_model.md,
// "Sensors"): "ideal" (no sensor; the controller reads the exact state),
// "mocap" (an IMU plus a motion-capture pose) and "onboard" (an IMU plus a GPS-class position).
// Every number and its source are in sensor_presets.cpp.
#include <string>

#include "sim/sensors/sensor_settings.h"

namespace cosim {

// Throws std::invalid_argument naming the known presets for any other name (the scenario loader
// turns it into an input error).
SensorSettings sensorPreset(const std::string& name);

}  // namespace cosim
