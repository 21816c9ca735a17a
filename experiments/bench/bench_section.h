#pragma once
// `cosim bench` is a list of sections; each measures two things in the same run (ours against a
// peer or the bare engine) and reports figures. A section lives in its own file here and is
// listed once in cli/cmd_bench.cpp.
#include <string>
#include <vector>

namespace cosim::bench {

struct Figure {
  std::string name;   // e.g. "astar_expansions_per_s"
  double value = 0.0;
  std::string unit;   // e.g. "1/s", "ms", "x"
};

struct Section {
  std::string name;   // e.g. "grid_astar_vs_boost"
  std::vector<Figure> figures;
  std::string note;   // one line: what was compared, and whether the target was met
  // Optional lines printed under the figures (a breakdown whose key numbers are also figures);
  // not in --json.
  std::string table;
};

// quick: a smaller workload (used by tests to check a section runs); full otherwise.
using SectionFunction = Section (*)(bool quick);

}  // namespace cosim::bench
