#include "sim/run_log.h"

#include <array>
#include <utility>

namespace cosim {

namespace {

constexpr std::array<std::pair<RunEnd, const char*>, 9> kRunEndNames = {{
    {RunEnd::Running, "running"},
    {RunEnd::Goal, "goal"},
    {RunEnd::MaxTime, "max_time"},
    {RunEnd::Interrupted, "interrupted"},
    {RunEnd::Diverged, "diverged"},
    {RunEnd::Unstable, "unstable"},
    {RunEnd::Saturated, "saturated"},
    {RunEnd::GaveUp, "gave_up"},
    {RunEnd::NoPath, "no_path"},
}};

}  // namespace

const char* runEndName(RunEnd end) {
  for (const auto& [e, name] : kRunEndNames)
    if (e == end) return name;
  return "unknown";
}

std::optional<RunEnd> runEndNamed(std::string_view name) {
  for (const auto& [e, n] : kRunEndNames)
    if (name == n) return e;
  return std::nullopt;
}

}  // namespace cosim
