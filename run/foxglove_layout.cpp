#include "run/foxglove_layout.h"

#include <algorithm>
#include <cctype>

namespace cosim {

using nlohmann::ordered_json;

std::filesystem::path foxgloveLayoutPathFor(const std::filesystem::path& mcap) {
  return mcap.parent_path() / (mcap.stem().string() + ".layout.json");
}

std::string foxgloveMessagePath(const std::string& topic, const std::string& field) {
  const bool plain = std::all_of(topic.begin(), topic.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '/';
  });
  if (plain) return topic + "." + field;
  std::string quoted = "\"";
  for (char c : topic) {
    if (c == '"' || c == '\\') quoted += '\\';
    quoted += c;
  }
  return quoted + "\"." + field;
}

namespace {

ordered_json series(const std::string& path, const std::string& label) {
  return {{"value", path}, {"enabled", true}, {"timestampMethod", "receiveTime"}, {"label", label}};
}

ordered_json plot(const std::string& title, ordered_json paths) {
  return {{"title", title},          {"paths", std::move(paths)}, {"showXAxisLabels", true},
          {"showYAxisLabels", true}, {"showLegend", true},        {"legendDisplay", "floating"},
          {"isSynced", true},        {"xAxisVal", "timestamp"}};
}

// The 3D panel: the world frame, the three scene topics on, the camera over the world's centre
// far enough back to see all of it (the distance as the overview picture's: the world's
// diagonal), tilted 50 degrees from the vertical (phi) for depth.
ordered_json threeD(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) {
  const Eigen::Vector3d centre = 0.5 * (lo + hi);
  const double diagonal = (hi - lo).norm();
  ordered_json camera = {{"perspective", true},
                         {"distance", std::max(1.0, diagonal)},
                         {"phi", 50.0},
                         {"thetaOffset", 45.0},
                         {"targetOffset", {centre.x(), centre.y(), centre.z()}},
                         {"target", {0, 0, 0}},
                         {"targetOrientation", {0, 0, 0, 1}},
                         {"fovy", 45.0},
                         {"near", 0.01},
                         {"far", std::max(5000.0, 10.0 * diagonal)}};
  ordered_json topics = ordered_json::object();
  for (const char* t : {"/world", "/vehicles", "/paths"}) topics[t] = {{"visible", true}};
  return {{"cameraState", std::move(camera)},
          {"followMode", "follow-none"},
          {"followTf", "world"},
          {"scene", {{"enableStats", false}}},
          {"transforms", ordered_json::object()},
          {"topics", std::move(topics)},
          {"layers", ordered_json::object()},
          {"publish", {{"type", "point"}}}};
}

}  // namespace

ordered_json foxgloveLayout(const std::vector<std::string>& vehicle_names,
                            const Eigen::Vector3d& bounds_min, const Eigen::Vector3d& bounds_max) {
  ordered_json position = ordered_json::array(), error = ordered_json::array();
  const std::size_t shown = std::min(vehicle_names.size(), kFoxgloveLayoutPlottedVehicles);
  for (std::size_t v = 0; v < shown; ++v) {
    const std::string& name = vehicle_names[v];
    const std::string topic = "/vehicles/" + name + "/state";
    for (const char* axis : {"x", "y", "z"})
      position.push_back(
          series(foxgloveMessagePath(topic, std::string("position.") + axis), name + " " + axis));
    error.push_back(series(foxgloveMessagePath(topic, "error_m"), name + " tracking error"));
    error.push_back(
        series(foxgloveMessagePath(topic, "estimate_error_m"), name + " estimation error"));
  }
  ordered_json layout;
  layout["configById"] = {{"3D!cosim", threeD(bounds_min, bounds_max)},
                          {"Plot!position", plot("Position [m]", std::move(position))},
                          {"Plot!error", plot("Error [m]", std::move(error))}};
  layout["globalVariables"] = ordered_json::object();
  layout["userNodes"] = ordered_json::object();
  layout["linkedGlobalVariables"] = ordered_json::array();
  layout["playbackConfig"] = {{"speed", 1.0}};
  layout["layout"] = {{"direction", "row"},
                      {"first", "3D!cosim"},
                      {"second",
                       {{"direction", "column"},
                        {"first", "Plot!position"},
                        {"second", "Plot!error"},
                        {"splitPercentage", 50}}},
                      {"splitPercentage", 60}};
  return layout;
}

}  // namespace cosim
