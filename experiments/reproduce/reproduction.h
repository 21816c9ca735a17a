#pragma once
// `cosim reproduce NAME` runs one of the seed documents' experiments and writes a markdown table
// that sets the seed's published numbers beside ours. Each reproduction lives in its own file
// here and is listed once in experiments/cli/cmd_reproduce.cpp.
#include <cstdint>
#include <string>

namespace cosim::reproduce {

struct Options {
  int runs = 0;             // repetitions per configuration; 0 = the reproduction's default
  std::uint64_t seed = 1;   // base seed; run i uses seed + i
  std::string out_dir;      // where to write <name>.md (and any CSV), already created
  bool quick = false;       // a small version for tests
};

// Returns the markdown report (also written to out_dir/<name>.md by the command).
using Function = std::string (*)(const Options& options);

struct Entry {
  const char* name;         // e.g. "seed003-discrete"
  const char* description;
  Function run;
};

}  // namespace cosim::reproduce
