#pragma once
// A Foxglove layout for a run's MCAP export (run/run_mcap.h), written beside the .mcap by
// `cosim export-mcap` so that the file opens ready to look at: a 3D panel showing /world,
// /vehicles and /paths in the `world` frame, looking at the whole world, and two plots against
// time, each vehicle's position (x, y, z) and its tracking and estimation errors. Foxglove's
// layout JSON ("Import layout from file"): configById (panel id "<Type>!<suffix>" -> the panel's
// settings), layout (the mosaic tree: a panel id, or {direction, first, second,
// splitPercentage}), globalVariables, userNodes, playbackConfig.
#include <Eigen/Core>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace cosim {

// Vehicles whose series the plots show: the first this many (a team of hundreds would draw an
// unreadable tangle; any other vehicle's topic can be added in the panel).
constexpr std::size_t kFoxgloveLayoutPlottedVehicles = 4;

// Where `cosim export-mcap` writes the layout of FILE.mcap: FILE.layout.json beside it.
std::filesystem::path foxgloveLayoutPathFor(const std::filesystem::path& mcap);

// The layout for a run of these vehicles in a world of these bounds.
nlohmann::ordered_json foxgloveLayout(const std::vector<std::string>& vehicle_names,
                                      const Eigen::Vector3d& bounds_min,
                                      const Eigen::Vector3d& bounds_max);

// A field of a topic as Foxglove's message path syntax writes it: `/vehicles/uav1/state.error_m`,
// the topic in double quotes (with \" and \\ escaped) when it holds anything but letters,
// digits, '_', '-' and '/'.
std::string foxgloveMessagePath(const std::string& topic, const std::string& field);

}  // namespace cosim
