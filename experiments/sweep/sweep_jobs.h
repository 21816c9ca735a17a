#pragma once
// The jobs of a sweep: every scenario (files first, then generated worlds, in file order) times
// every combination of the varied values (the first `vary:` key varies slowest). A job's id is its
// index in this order, so ids, folders and result rows are the same on every machine and shard.
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "experiments/sweep/sweep_spec.h"

namespace cosim {

struct SweepJob {
  std::size_t id = 0;
  std::string scenario;  // the results' scenario column
  std::filesystem::path scenario_path;
  std::vector<std::string> values;     // one per SweepSpec::vary entry, same order
  std::vector<std::string> overrides;  // "key=value" for `cosim run --set`: fixed, then varied
  // Hash of the scenario text, the overrides and every file the job's run reads (grid map, world
  // fragment and its meshes, URDFs and their meshes; sim/scenario_input_files.h): a finished
  // result only counts for the inputs it was made from (a changed scenario file, sweep file or
  // included file reruns the jobs it affects).
  std::string fingerprint;
};

// Expands the grid. Generated worlds are written to out_dir/worlds/ (rewritten only when their
// text changes, so concurrent shards agree). Throws InputError for generator defects.
std::vector<SweepJob> expandSweepJobs(const SweepSpec& spec, const std::filesystem::path& out_dir);

// Loads every job's scenario with its overrides (strict loader) and builds its planner, so an
// unknown key, a bad value or an unknown planner parameter stops the sweep before it starts.
// Throws InputError naming the sweep file, the vary/set key involved and the problem.
// Returns early (having checked only some jobs) once the process is asked to stop.
void validateSweepJobs(const SweepSpec& spec, const std::vector<SweepJob>& jobs);

// The job's folder name: its id, zero-padded to the width of the largest id (at least 4 digits).
std::string sweepJobDirName(std::size_t id, std::size_t job_count);

}  // namespace cosim
