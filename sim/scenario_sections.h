#pragma once
// The sections of a scenario file, each read by its own part of the loader. loadScenario
// (sim/scenario_loader.cpp) reads the document and calls them in the order below, which is also
// the order their errors are found in: a later section is checked against what the earlier ones
// read (a vehicle's start against the world, the sensing rates against the physics rate). Each
// reader takes the whole document `root` (its top-level keys already checked) and throws
// InputError (file, line and key, problem) through the YamlReader.
#include <yaml-cpp/yaml.h>

#include <Eigen/Core>
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "sim/scenario.h"
#include "sim/yaml_reader.h"

namespace cosim {

constexpr double kMaxWorldExtent = 10000.0;    // m; larger worlds are surely a units mistake
constexpr std::size_t kMaxWaypoints = 100000;  // a vehicle's waypoints, a moving obstacle's path

// world: bounds and obstacles, or a grid map; moving obstacles; an MJCF include
// (sim/scenario_world.cpp). `dir` is the scenario's folder, where relative file names start.
void readWorldSection(const YamlReader& r, const YAML::Node& root, const std::filesystem::path& dir,
                      Scenario& s);
// Throws at `key` unless p is inside the world's bounds and outside every obstacle.
void checkPointPlacement(const YamlReader& r, const YAML::Node& n, const std::string& key,
                         const Scenario& s, const Eigen::Vector3d& p);

// vehicles: names, models, starts, goals or waypoints, given references, masses
// (sim/scenario_vehicles.cpp).
void readVehiclesSection(const YamlReader& r, const YAML::Node& root,
                         const std::filesystem::path& dir, Scenario& s);

// planner, trajectory and controller, and the `aerial` ones of quadrotors over ground robots
// (sim/scenario_motion.cpp). `overrides` place the parameters' errors at their --set.
void readMotionSections(const YamlReader& r, const YAML::Node& root,
                        const std::vector<std::string>& overrides, Scenario& s);

// vehicles[i].battery and vehicles[i].motor_speed_map of one vehicle node (sim/scenario_power.cpp,
// called by readVehiclesSection).
void readVehiclePower(const YamlReader& r, const YAML::Node& n, const std::string& key,
                      VehicleSpec& v);
// controller.thrust_map, thrust_map_coefficients, idle_thrust, platform of the controller node c
// (`prefix`: "" or "aerial."), for the controller `name` (only the crazyflie_* ones take them).
CrazyflieThrustPath readCrazyflieThrustPath(const YamlReader& r, const YAML::Node& c,
                                            const std::string& prefix, const std::string& name);
// After the motion sections: batteries and motor maps only under a crazyflie_* controller; a
// default battery for every quadrotor flown with thrust_map pwm_quadratic that has none.
void checkVehiclePower(const YamlReader& r, const YAML::Node& root, Scenario& s);

// sim: timestep, control rate, length, seed, goal tolerance; then what depends on them (a
// Crazyflie controller's rate, the log's size, given references' starts)
// (sim/scenario_sim_settings.cpp).
void readSimSection(const YamlReader& r, const YAML::Node& root, Scenario& s);

// disturbances: drag, wind and gusts, ground effect, downwash (sim/scenario_disturbances.cpp).
void readDisturbancesSection(const YamlReader& r, const YAML::Node& root, Scenario& s);

// sensors, estimator and model_error: sim/scenario_sensing.h.

// render: cameras, frame size and rate, speed-up, obstacles' opacity, frames, team plans
// (sim/scenario_render_settings.cpp).
void readRenderSection(const YamlReader& r, const YAML::Node& root, Scenario& s);

}  // namespace cosim
