#include "experiments/sweep/sweep_jobs.h"

#include <cstdint>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>

#include "core/atomic_file.h"
#include "core/input_error.h"
#include "core/output_files.h"
#include "core/stop_request.h"
#include "experiments/sweep/generated_scenario.h"
#include "planning/planner_registry.h"
#include "run/scenario_checks.h"
#include "sim/scenario.h"
#include "sim/scenario_input_files.h"

namespace cosim {

namespace {

std::string readText(const std::filesystem::path& p, const std::string& place,
                     const std::filesystem::path& sweep) {
  std::ifstream in(p, std::ios::binary);
  if (!in) throw InputError(sweep.string(), place, "cannot read scenario file " + p.string());
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// FNV-1a, 64 bit: a stable content hash (std::hash is not stable across builds).
class Fnv1a {
 public:
  void add(const char* data, std::size_t n) {
    for (std::size_t i = 0; i < n; ++i)
      h_ = (h_ ^ static_cast<unsigned char>(data[i])) * 1099511628211ull;
  }
  // A string, then a separator: ("ab","c") != ("a","bc").
  void addField(const std::string& s) {
    add(s.data(), s.size());
    h_ = (h_ ^ 0xff) * 1099511628211ull;
  }
  std::string hex() const {
    char buf[20];
    std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h_));
    return buf;
  }

 private:
  std::uint64_t h_ = 1469598103934665603ull;
};

// The content hash of one input file, or what stands in its place ("missing", "not a regular
// file"), read in pieces (a grid map may be hundreds of megabytes).
std::string fileDigest(const std::filesystem::path& p) {
  std::error_code ec;
  const auto status = std::filesystem::status(p, ec);
  if (ec || !std::filesystem::exists(status)) return "missing";
  if (!std::filesystem::is_regular_file(status)) return "not a regular file";
  std::ifstream in(p, std::ios::binary);
  if (!in) return "unreadable";
  Fnv1a h;
  char buffer[1 << 16];
  while (in.read(buffer, sizeof buffer) || in.gcount() > 0)
    h.add(buffer, static_cast<std::size_t>(in.gcount()));
  return h.hex();
}

// A job's fingerprint: its scenario text, its overrides and every file the run reads (the grid
// map, the world fragment and its meshes, URDFs and theirs), so that a result only counts for
// the inputs it was made from. `digests` caches file hashes across jobs.
std::string fingerprint(const std::string& scenario_text, const std::filesystem::path& scenario,
                        const std::vector<std::string>& overrides,
                        std::map<std::filesystem::path, std::string>& digests) {
  Fnv1a h;
  h.addField(scenario_text);
  for (const auto& o : overrides) h.addField(o);
  for (const auto& f : scenarioInputFiles(scenario_text, scenario.string(), overrides)) {
    auto it = digests.find(f);
    if (it == digests.end()) it = digests.emplace(f, fileDigest(f)).first;
    h.addField(f.string());
    h.addField(it->second);
  }
  return h.hex();
}

// "line 3, key planner.step" names planner.step and planner, not planner.s.
bool placeNamesKey(const std::string& place, const std::string& key) {
  // An override refused before it reached a key: "--set vehicles[3].goal=...".
  if (place.rfind("--set " + key + "=", 0) == 0) return true;
  const auto at = place.find("key " + key);
  if (at == std::string::npos) return false;
  const std::size_t end = at + 4 + key.size();
  return end == place.size() || place[end] == '.' || place[end] == '[' || place[end] == ',';
}

struct ScenarioSource {
  std::string column;
  std::filesystem::path path;
  std::string text;
};

}  // namespace

std::string sweepJobDirName(std::size_t id, std::size_t job_count) {
  const std::size_t width =
      std::max<std::size_t>(4, std::to_string(job_count > 0 ? job_count - 1 : 0).size());
  std::string s = std::to_string(id);
  return std::string(width > s.size() ? width - s.size() : 0, '0') + s;
}

std::vector<SweepJob> expandSweepJobs(const SweepSpec& spec, const std::filesystem::path& out_dir) {
  std::vector<ScenarioSource> sources;
  for (const auto& f : spec.scenarios)
    sources.push_back({f.as_written, f.path, readText(f.path, f.place, spec.file)});
  for (const auto& g : spec.generators)
    for (double density : g.densities)
      for (long seed : g.seeds) {
        const std::string name = generatedScenarioName(g, density, seed);
        const std::string text = generatedScenarioYaml(g, density, seed, spec.file.string());
        const auto path = out_dir / "worlds" / name;
        std::error_code ec;
        std::filesystem::create_directories(path.parent_path(), ec);
        std::ifstream existing(path, std::ios::binary);
        std::ostringstream old;
        if (existing) old << existing.rdbuf();
        if (!existing || old.str() != text) writeFileAtomically(path, text);
        sources.push_back({"worlds/" + name, path, text});
      }

  std::vector<std::string> fixed;
  for (const auto& [k, v] : spec.fixed) fixed.push_back(k + "=" + v);
  std::size_t combinations = 1;
  for (const auto& v : spec.vary) combinations *= v.values.size();

  std::vector<SweepJob> jobs;
  jobs.reserve(sources.size() * combinations);
  std::map<std::filesystem::path, std::string> digests;
  for (const auto& src : sources)
    for (std::size_t c = 0; c < combinations; ++c) {
      SweepJob job;
      job.id = jobs.size();
      job.scenario = src.column;
      job.scenario_path = src.path;
      job.overrides = fixed;
      // Mixed-radix digits of c, the last key fastest.
      std::size_t rest = c;
      job.values.resize(spec.vary.size());
      for (std::size_t k = spec.vary.size(); k-- > 0;) {
        const auto& var = spec.vary[k];
        job.values[k] = var.values[rest % var.values.size()];
        rest /= var.values.size();
      }
      for (std::size_t k = 0; k < spec.vary.size(); ++k)
        job.overrides.push_back(spec.vary[k].key + "=" + job.values[k]);
      job.fingerprint = fingerprint(src.text, src.path, job.overrides, digests);
      jobs.push_back(std::move(job));
    }
  return jobs;
}

void validateSweepJobs(const SweepSpec& spec, const std::vector<SweepJob>& jobs) {
  std::map<std::filesystem::path, std::string> texts;
  for (const auto& job : jobs) {
    if (stopRequested()) return;  // the caller reports the interruption
    auto& text = texts[job.scenario_path];
    if (text.empty()) text = readText(job.scenario_path, "scenario " + job.scenario, spec.file);
    try {
      Scenario s = parseScenario(text, job.scenario_path.string(), job.overrides);
      checkRunPlanners(s);  // team planners and navigators too, as the run builds them
    } catch (const InputError& e) {
      // Name the sweep file's key behind the problem when there is one.
      std::string place = "job " + std::to_string(job.id);
      for (const auto& [k, value] : spec.fixed)
        if (placeNamesKey(e.place(), k)) place = "key set." + k;
      for (const auto& v : spec.vary)
        if (placeNamesKey(e.place(), v.key)) place = v.place;
      std::string with;
      for (std::size_t k = 0; k < spec.vary.size(); ++k)
        with += (k ? ", " : " with ") + spec.vary[k].key + "=" + job.values[k];
      throw InputError(spec.file.string(), place,
                       "scenario " + job.scenario + with + ": " + e.what());
    }
  }
}

}  // namespace cosim
