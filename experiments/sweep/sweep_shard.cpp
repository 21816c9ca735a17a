#include "experiments/sweep/sweep_shard.h"

#include <cstdlib>

#include "core/input_error.h"

namespace cosim {

namespace {

bool parsePositive(const std::string& s, long& out) {
  if (s.empty() || s.size() > 9) return false;
  for (char c : s)
    if (c < '0' || c > '9') return false;
  out = std::strtol(s.c_str(), nullptr, 10);
  return true;
}

}  // namespace

SweepShard parseSweepShard(const std::string& text,
                           const std::function<const char*(const char*)>& env) {
  long index = 0, count = 0;
  if (text == "auto") {
    const char* id = env("SLURM_ARRAY_TASK_ID");
    if (!id) return {};
    const char* min = env("SLURM_ARRAY_TASK_MIN");
    const char* n = env("SLURM_ARRAY_TASK_COUNT");
    long task = 0, first = 0;
    if (!parsePositive(id, task) || !n || !parsePositive(n, count) ||
        (min && !parsePositive(min, first)))
      throw InputError("environment", "--shard auto",
                       "SLURM_ARRAY_TASK_ID/MIN/COUNT are not whole numbers");
    index = task - first + 1;
    if (count < 1 || index < 1 || index > count)
      throw InputError("environment", "--shard auto",
                       "task " + std::string(id) + " is outside a contiguous array of " +
                           std::to_string(count) + " tasks (use --array=A-B)");
    return {static_cast<int>(index), static_cast<int>(count)};
  }
  const auto slash = text.find('/');
  if (slash == std::string::npos || !parsePositive(text.substr(0, slash), index) ||
      !parsePositive(text.substr(slash + 1), count) || count < 1 || index < 1 || index > count)
    throw InputError("command line", "--shard " + text, "expected I/N with 1 <= I <= N, or auto");
  return {static_cast<int>(index), static_cast<int>(count)};
}

}  // namespace cosim
