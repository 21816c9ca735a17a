#pragma once
// The bad inputs that bad_input_test.cpp gives the built program, by topic: scenario contents
// (bad_scenario_inputs.cpp), the command line and MovingAI files (bad_command_line_inputs.cpp),
// and what an adversarial probe broke: resource limits, YAML structure, special files
// (bad_input_hardening.cpp). Here: one case, and the small valid scenario the cases break.
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace cosim::test {

// A small valid scenario, and pieces to break.
inline const std::string kWorld =
    "world: {bounds: {min: [0, 0, 0], max: [20, 20, 6]},\n"
    "        obstacles: [{type: box, pos: [10, 10, 3], size: [2, 8, 6]}]}\n";
inline const std::string kVehicle =
    "vehicles: [{name: uav1, model: cf2, start: [2, 2, 1], goal: [18, 18, 1]}]\n";
inline const std::string kPlanner = "planner: {name: astar, resolution: 0.5}\n";
inline const std::string kValid = kWorld + kVehicle + kPlanner;

inline std::string withWorld(const std::string& world) {
  return world + kVehicle + kPlanner;
}
inline std::string withVehicles(const std::string& vehicles) {
  return kWorld + vehicles + kPlanner;
}
inline std::string withPlanner(const std::string& planner) {
  return kWorld + kVehicle + planner;
}

inline std::string mapText(int w, int h, const std::string& rows) {
  return "type octile\nheight " + std::to_string(h) + "\nwidth " + std::to_string(w) + "\nmap\n" +
         rows;
}

struct BadInput {
  std::string name;
  // {in} is replaced by the file holding `content`, {in2} by the one holding `content2`, {out}
  // by a fresh output path, {dir} by the case's folder (the program runs there).
  std::string args;
  std::string content, content2;
  int exit_code;
  std::string message;  // the stderr line must contain this ({in}, {dir} as in args)
  // More files in the case's folder (name relative to it, content), and a FIFO to make there.
  std::vector<std::pair<std::string, std::string>> files = {};
  std::string fifo = "";
};

inline void PrintTo(const BadInput& c, std::ostream* os) {
  *os << c.name;
}

// The commands most cases run ({in}, {in2} and {out} as in BadInput::args).
inline const std::string kPlanCommand = "plan {in} --out {out}";
inline const std::string kRunCommand = "run {in} --no-video --out {out}";
inline const std::string kGridBenchCommand =
    "grid-bench {in} {in2} --planner astar --out {out}/bench.csv";

// A free 8 x 8 MovingAI map, and a scenario file of one line on it.
inline std::string freeMap8() {
  std::string rows8;
  for (int i = 0; i < 8; ++i) rows8 += "........\n";
  return mapText(8, 8, rows8);
}
inline const std::string kScen8 = "version 1\n0\tx.map\t8\t8\t0\t0\t7\t7\t9.89949494\n";

std::vector<BadInput> badScenarioInputs();
std::vector<BadInput> badCommandLineInputs();
std::vector<BadInput> hardeningBadInputs();

}  // namespace cosim::test
