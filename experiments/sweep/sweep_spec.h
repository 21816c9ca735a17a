#pragma once
// A sweep file, read and checked: which scenarios (files, or worlds to generate) to run, which
// scenario keys to vary over which values (every combination is one job), fixed overrides, output
// options and limits. Format: experiments/sweeps/example.yaml (commented).
#include <filesystem>
#include <string>
#include <vector>

namespace cosim {

// One world generator entry; lists of seeds/densities expand to one world each.
struct GeneratorSpec {
  std::string type;  // forest | city | maze
  std::vector<double> densities;
  std::vector<long> seeds;
  double size[3] = {50, 50, 10};
  double cell = 3.0;  // maze only: m per maze cell
  std::string place;  // "line 7, key generators[0]" for messages
};

struct SweepVariable {
  std::string key;                  // a dotted scenario key, e.g. planner.name
  std::vector<std::string> values;  // each a YAML value as it goes to --set (flow style)
  std::string place;
};

struct SweepScenarioFile {
  std::string as_written;      // the results' `scenario` column
  std::filesystem::path path;  // resolved (see resolveSweepScenarioPath)
  std::string place;
};

struct SweepSpec {
  std::filesystem::path file;
  std::string name;  // the file's stem unless `name:` says otherwise
  std::vector<SweepScenarioFile> scenarios;
  std::vector<GeneratorSpec> generators;
  std::vector<SweepVariable> vary;  // in file order: the first key varies slowest
  std::vector<std::pair<std::string, std::string>> fixed;  // `set:` overrides for every job
  bool video = false;
  std::string figure_metric = "planned_length_m";
  std::string figure_by;  // the varied key whose values are the figure's bars ("": the
                          // first varied key that is not a seed)
  double job_timeout_s = 600.0;
  double kill_grace_s = 5.0;  // SIGTERM -> SIGKILL delay for a job past its time limit
};

// Reads a sweep file. Throws InputError (file, line and key, problem) on any defect, including
// scenario files that cannot be found.
SweepSpec loadSweepSpec(const std::filesystem::path& file);
SweepSpec parseSweepSpec(const std::string& text, const std::filesystem::path& file);

// Scenario paths: absolute paths as they are; a relative path is looked up next to the sweep file
// first, then in the current directory (so both `../scenarios/x.yaml` in a sweep file beside the
// scenarios and `experiments/scenarios/x.yaml` run from the repository root work). Returns an
// empty path if neither exists.
std::filesystem::path resolveSweepScenarioPath(const std::string& written,
                                               const std::filesystem::path& sweep_file);

}  // namespace cosim
