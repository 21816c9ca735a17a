#include "experiments/bench/ompl_benchmark_log.h"

#include <set>
#include <sstream>

namespace cosim {

namespace {

// A block of free text between "<<<|" and "|>>>" lines; the reader stops at the first line that
// starts with "|>>>", so the text must end with a line break and no line may start that way.
void textBlock(std::ostringstream& out, std::string text) {
  if (!text.empty() && text.back() != '\n') text += '\n';
  std::string safe;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);)
    safe += (line.rfind("|>>>", 0) == 0 ? " " : "") + line + "\n";
  out << "<<<|\n" << safe << "|>>>\n";
}

// One line, no line breaks (names and values of properties are read line by line).
std::string oneLine(std::string s) {
  for (char& c : s)
    if (c == '\n' || c == '\r') c = ' ';
  return s;
}

}  // namespace

std::string omplBenchmarkLog(const OmplLogExperiment& e,
                             const std::vector<std::string>& status_names) {
  std::ostringstream out;
  out.precision(17);
  out << "OMPL version " << oneLine(e.version) << "\n";
  out << "Experiment " << (e.name.empty() ? "NO_NAME" : oneLine(e.name)) << "\n";
  out << e.properties.size() << " experiment properties\n";
  for (const auto& [name, value] : e.properties) out << name << " = " << oneLine(value) << "\n";
  out << "Running on " << (e.host.empty() ? "UNKNOWN" : oneLine(e.host)) << "\n";
  out << "Starting at " << e.start_time << "\n";
  textBlock(out, e.setup);
  textBlock(out, e.cpu);
  out << e.seed << " is the random seed\n";
  out << e.time_limit_s << " seconds per run\n";
  out << e.memory_limit_mb << " MB per run\n";
  out << e.runs_per_planner << " runs per planner\n";
  out << e.total_s << " seconds spent to collect the data\n";
  out << "1 enum type\nstatus";
  for (const std::string& s : status_names) out << '|' << s;
  out << "\n" << e.planners.size() << " planners\n";
  for (const OmplLogPlanner& p : e.planners) {
    out << oneLine(p.name) << "\n" << p.common.size() << " common properties\n";
    for (const auto& [name, value] : p.common) out << name << " = " << oneLine(value) << "\n";
    std::set<std::string> properties;  // sorted, as OMPL writes them
    for (const auto& run : p.runs)
      for (const auto& entry : run) properties.insert(entry.first);
    out << properties.size() << " properties for each run\n";
    for (const std::string& name : properties) out << name << "\n";
    out << p.runs.size() << " runs\n";
    for (const auto& run : p.runs) {
      for (const std::string& name : properties) {
        const auto it = run.find(name);
        if (it != run.end()) out << oneLine(it->second);
        out << "; ";
      }
      out << "\n";
    }
    out << ".\n";
  }
  return out.str();
}

}  // namespace cosim
