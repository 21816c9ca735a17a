#pragma once
// `cosim reproduce NAME` runs one of the seed documents' experiments and writes a markdown table
// that sets the seed's published numbers beside ours (NAME.md), and the same cells as data
// (NAME.json, docs/reproductions.md). Each reproduction lives in its own file here and is
// listed once in cli/cmd_reproduce.cpp; report_files.h writes both files.
#include <cstdint>
#include <string>
#include <vector>

#include "core/json_writer.h"

namespace cosim::reproduce {

struct Options {
  int runs = 0;            // repetitions per configuration; 0 = the reproduction's default
  std::uint64_t seed = 1;  // base seed; run i uses seed + i
  std::string out_dir;     // where to write <name>.md (and any CSV), already created
  bool quick = false;      // a small version for tests
};

// What a reproduction returns: the markdown report and one JSON object per table cell group
// (NAME.json's "rows"). The --quick marking of both files is added by report_files.h.
struct Report {
  std::string markdown;
  std::vector<JsonObject> rows;
  // Wall-clock time of the whole run [s], set by `cosim reproduce` (< 0: not timed); written to
  // both files (docs/reproductions.md quotes it from NAME.json).
  double run_time_s = -1.0;
};

using Function = Report (*)(const Options& options);

struct Entry {
  const char* name;  // e.g. "seed003-discrete"
  const char* description;
  Function run;
};

}  // namespace cosim::reproduce
