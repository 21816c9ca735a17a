#pragma once
// A deterministic slice of a sweep, so N machines (or N Slurm array tasks) share one sweep: shard
// I of N runs the jobs whose id % N == I - 1 (round robin, which spreads every scenario and
// planner over all shards).
#include <cstddef>
#include <functional>
#include <string>

namespace cosim {

struct SweepShard {
  int index = 1;  // 1-based
  int count = 1;
  bool owns(std::size_t job_id) const { return static_cast<int>(job_id % count) == index - 1; }
  bool whole() const { return count == 1; }
};

// "I/N" (1 <= I <= N), or "auto": from Slurm's job-array variables SLURM_ARRAY_TASK_ID,
// SLURM_ARRAY_TASK_MIN and SLURM_ARRAY_TASK_COUNT (shard ID - MIN + 1 of COUNT; the array must be
// contiguous, e.g. --array=1-4), or the whole sweep when not inside a job array. `env` looks up an
// environment variable (nullptr when unset). Throws InputError (place "--shard") when malformed.
SweepShard parseSweepShard(const std::string& text,
                           const std::function<const char*(const char*)>& env);

}  // namespace cosim
