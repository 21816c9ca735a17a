#pragma once
// Reading a vehicle's `reference:` (part of sim/scenario_loader.cpp, kept apart because it is one
// concept: a given reference flown instead of a planned path):
//   vehicles:
//     - {name: cf, model: cf2, start: [0, 0, 1], reference: {file: figure8.csv, timescale: 0.5,
//                                                            relative: true}}
// `file` (relative to the scenario's folder) is read by control/reference_file.h; `timescale`
// [1] stretches time as the Crazyflie's startTrajectory(timescale) does; `relative` [false] adds
// the start to every point.
#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <string>

#include "sim/scenario.h"
#include "sim/yaml_reader.h"

namespace cosim {

// Reads `vehicle`'s reference (the node vehicle["reference"]) into v: v.reference placed,
// v.reference_file, and v.waypoints = {the reference's last point} (its goal). `key` is the
// vehicle's ("vehicles[0]"); s.world must be read (the reference must stay inside its bounds).
// A ground robot, or a vehicle that also has a goal or waypoints, is an error; so is a bad file
// (InputError naming the reference file and its line).
void readVehicleReference(const YamlReader& r, const YAML::Node& vehicle, const std::string& key,
                          const std::filesystem::path& scenario_dir, const Scenario& s,
                          VehicleSpec& v);

// Once s.sim is read: each reference starts within sim.goal_tolerance of its vehicle's start
// (the vehicle starts at rest in hover there; a reference elsewhere would make it jump).
void checkReferenceStarts(const YamlReader& r, const YAML::Node& root, const Scenario& s);

}  // namespace cosim
