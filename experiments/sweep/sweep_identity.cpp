#include "experiments/sweep/sweep_identity.h"

#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/atomic_file.h"
#include "core/crc32.h"
#include "core/input_error.h"
#include "core/json_writer.h"

namespace cosim {

namespace {

constexpr const char* kSweepStateFile = "sweep-state.json";

// One line per thing that decides what a job id means; the same spec gives the same text.
std::string sweepGridText(const SweepSpec& spec) {
  std::ostringstream s;
  s.precision(17);
  s << "name " << spec.name << "\n";
  for (const auto& f : spec.scenarios) s << "scenario " << f.as_written << "\n";
  for (const auto& g : spec.generators) {
    s << "generator " << g.type << " size " << g.size[0] << " " << g.size[1] << " " << g.size[2]
      << " cell " << g.cell << " densities";
    for (double d : g.densities) s << " " << d;
    s << " seeds";
    for (long seed : g.seeds) s << " " << seed;
    s << "\n";
  }
  for (const auto& v : spec.vary) {
    s << "vary " << v.key;
    for (const auto& value : v.values) s << " [" << value << "]";
    s << "\n";
  }
  for (const auto& [k, v] : spec.fixed) s << "set " << k << "=" << v << "\n";
  return s.str();
}

}  // namespace

std::string sweepGridFingerprint(const SweepSpec& spec) {
  char hex[9];
  std::snprintf(hex, sizeof hex, "%08x", crc32(sweepGridText(spec)));
  return hex;
}

void checkSweepFolderHoldsThisSweep(const SweepSpec& spec, const std::filesystem::path& out_dir) {
  std::ifstream in(out_dir / kSweepStateFile);
  if (!in) return;
  std::ostringstream text;
  text << in.rdbuf();
  const nlohmann::json j = nlohmann::json::parse(text.str(), nullptr, /*allow_exceptions=*/false);
  const std::string held = j.is_object() && j.contains("grid") && j["grid"].is_string()
                               ? j["grid"].get<std::string>()
                               : "";
  const std::string mine = sweepGridFingerprint(spec);
  if (held == mine) return;
  const std::string other_name = j.is_object() && j.contains("sweep") && j["sweep"].is_string()
                                     ? j["sweep"].get<std::string>()
                                     : "?";
  throw InputError(out_dir.string(), "--out",
                   "holds another sweep ('" + other_name + "', grid " +
                       (held.empty() ? std::string("unreadable") : held) + "; " +
                       spec.file.string() + " has grid " + mine +
                       "): its jobs and tables would be mixed with this one's; choose another "
                       "--out folder");
}

std::string sweepState(std::size_t finished, std::size_t jobs) {
  if (finished >= jobs) return "complete";
  return "partial: " + std::to_string(finished) + " of " + std::to_string(jobs) + " jobs";
}

void writeSweepState(const SweepSpec& spec, const std::filesystem::path& out_dir,
                     std::size_t finished, std::size_t jobs) {
  writeFileAtomically(out_dir / kSweepStateFile, JsonObject()
                                                         .add("sweep", spec.name)
                                                         .add("grid", sweepGridFingerprint(spec))
                                                         .add("jobs", jobs)
                                                         .add("finished", finished)
                                                         .add("state", sweepState(finished, jobs))
                                                         .str() +
                                                     "\n");
}

}  // namespace cosim
