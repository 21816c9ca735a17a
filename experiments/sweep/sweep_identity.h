#pragma once
// Which sweep a folder holds, and how far it got: DIR/sweep-state.json records the fingerprint of
// the sweep's grid (its name, scenario files, generated worlds, varied keys and values and fixed
// overrides: what decides which job id means what), the number of jobs and the state ("complete",
// or "partial: N of M jobs" while jobs are missing). A sweep with another grid is refused in a
// folder holding one (its job folders and tables would be mixed with this one's); editing a
// scenario file, the sweep's limits or its output settings keeps the grid (the jobs whose inputs
// changed run again, as before).
#include <cstddef>
#include <filesystem>
#include <string>

#include "experiments/sweep/sweep_spec.h"

namespace cosim {

// The grid's fingerprint (8 hex digits, CRC-32 of its canonical text).
std::string sweepGridFingerprint(const SweepSpec& spec);

// Throws InputError(out_dir, "--out", "holds another sweep ...") if out_dir/sweep-state.json
// names another grid. A folder without one passes (a new folder; core/output_manifest.h guards
// what is in it).
void checkSweepFolderHoldsThisSweep(const SweepSpec& spec, const std::filesystem::path& out_dir);

// The state line: "complete" when every job has a result, else "partial: N of M jobs".
std::string sweepState(std::size_t finished, std::size_t jobs);

// Writes out_dir/sweep-state.json for this sweep.
void writeSweepState(const SweepSpec& spec, const std::filesystem::path& out_dir,
                     std::size_t finished, std::size_t jobs);

}  // namespace cosim
