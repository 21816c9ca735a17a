#include "cli/mapf_execution.h"

#include <yaml-cpp/yaml.h>

namespace cosim::cli {

namespace {

YAML::Node flowSequence(std::initializer_list<double> values) {
  YAML::Node n(YAML::NodeType::Sequence);
  for (double v : values) n.push_back(v);
  n.SetStyle(YAML::EmitterStyle::Flow);
  return n;
}

}  // namespace

std::string mapfExecutionScenarioYaml(const MapfExecutionSetup& m) {
  YAML::Node root;
  YAML::Node grid;
  grid["file"] = m.map_path;
  grid["cell"] = m.cell;
  if (!m.extra_blocked.empty()) {
    YAML::Node blocked(YAML::NodeType::Sequence);
    for (const Cell& c : m.extra_blocked)
      blocked.push_back(flowSequence({static_cast<double>(c.x), static_cast<double>(c.y)}));
    grid["blocked"] = blocked;
  }
  root["world"]["grid_map"] = grid;

  // Robot i stands on the centre of its start cell and ends on the centre of its goal cell.
  const auto centre = [&](const Cell& c) {
    return flowSequence({(c.x + 0.5) * m.cell, (c.y + 0.5) * m.cell, 0.0});
  };
  YAML::Node vehicles(YAML::NodeType::Sequence);
  for (std::size_t i = 0; i < m.starts.size(); ++i) {
    YAML::Node v;
    std::string name = "a";  // (not "a" + to_string: GCC 12 warns falsely, -Wrestrict)
    name += std::to_string(i);
    v["name"] = name;
    v["model"] = m.robot;
    v["start"] = centre(m.starts[i]);
    v["goal"] = centre(m.goals[i]);
    v.SetStyle(YAML::EmitterStyle::Flow);
    vehicles.push_back(v);
  }
  root["vehicles"] = vehicles;

  YAML::Node planner;
  planner["name"] = m.planner;
  // A robot of the default model (radius 0.15 m) keeps 0.05 m from the cell's edge on 0.5 m cells.
  planner["margin"] = "0.05";
  planner["connectivity"] = m.connectivity;
  planner["time_limit"] = m.time_limit_s;
  for (const std::string& kv : m.planner_sets) {
    const auto eq = kv.find('=');  // checked by applySetOptions before
    planner[kv.substr(0, eq)] = YAML::Load(kv.substr(eq + 1));
  }
  root["planner"] = planner;
  // Ground robots need no fine physics step: 2 ms, control at 50 Hz (as ground_team.yaml).
  YAML::Node sim;
  sim["timestep"] = 0.002;
  sim["control_rate"] = 50;
  sim["max_time"] = m.max_time_s;
  sim["seed"] = m.seed;
  root["sim"] = sim;
  root["render"]["camera"] = "top";
  if (m.video_speed > 0) root["render"]["speed"] = m.video_speed;

  YAML::Emitter out;
  out << root;
  return "# Written by cosim mapf --execute: the MAPF instance as a scenario (cosim run can re-run "
         "it).\n" +
         std::string(out.c_str()) + "\n";
}

}  // namespace cosim::cli
