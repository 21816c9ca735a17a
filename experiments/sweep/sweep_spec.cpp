#include "experiments/sweep/sweep_spec.h"

#include <cctype>
#include <fstream>
#include <set>
#include <sstream>

#include "core/input_error.h"
#include "core/input_file.h"
#include "sim/yaml_document.h"
#include "sim/yaml_reader.h"

namespace cosim {

namespace {

constexpr std::size_t kMaxJobs = 1000000;

// A value as `--set key=value` takes it: scalars as written, lists and maps in YAML flow style.
std::string overrideValue(const YAML::Node& n) {
  if (n.IsScalar()) return n.Scalar();
  YAML::Emitter e;
  e << YAML::Flow << n;
  return e.c_str();
}

// Letters, digits, '_' and '.' (and, with `indexed`, the brackets of vehicles[0]); the form of
// the brackets is overridePathProblem's to check.
bool isScenarioKey(const std::string& key, bool indexed = false) {
  if (key.empty() || key.front() == '.' || key.back() == '.' || key.find("..") != std::string::npos)
    return false;
  for (char c : key)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.' ||
          (indexed && (c == '[' || c == ']'))))
      return false;
  return true;
}

// Why `name` cannot be a folder name ("" if it can): letters, digits, '.', '_' and '-', at most
// 64, not starting with '.' (no "..", no hidden folders).
std::string unsafeNameReason(const std::string& name) {
  if (name.size() > 64) return "longer than 64 characters";
  if (name.front() == '.') return "starts with '.'";
  for (const char c : name)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '_' || c == '-'))
      return "only letters, digits, '.', '_' and '-' are allowed";
  return "";
}

// `set:` accepts dotted keys and nested maps alike; both become dotted overrides. The depth of
// this recursion is bounded by loadYamlDocument (kMaxYamlDepth).
void flattenOverrides(const YamlReader& r, const YAML::Node& n, const std::string& prefix,
                      std::vector<std::pair<std::string, std::string>>& out) {
  r.requireMap(n, prefix.empty() ? "set" : "set." + prefix);
  for (const auto& kv : n) {
    const std::string key = prefix.empty() ? kv.first.Scalar() : prefix + "." + kv.first.Scalar();
    if (!isScenarioKey(key)) r.fail(kv.first, "set." + key, "not a scenario key (a.b.c)");
    if (kv.second.IsMap())
      flattenOverrides(r, kv.second, key, out);
    else
      out.emplace_back(key, overrideValue(kv.second));
  }
}

template <typename T, typename Read>
std::vector<T> oneOrMany(const YAML::Node& n, const std::string& key, Read read) {
  std::vector<T> out;
  if (n.IsSequence()) {
    for (std::size_t i = 0; i < n.size(); ++i)
      out.push_back(read(n[i], key + "[" + std::to_string(i) + "]"));
  } else {
    out.push_back(read(n, key));
  }
  return out;
}

GeneratorSpec readGenerator(const YamlReader& r, const YAML::Node& n, const std::string& key) {
  r.requireMap(n, key);
  if (!n["type"]) r.fail(n, key, "generator needs a 'type' (forest, city or maze)");
  GeneratorSpec g;
  g.place = r.place(n, key);
  g.type = r.text(n["type"], key + ".type");
  double max_density = 1.0, default_density = 0.5;
  if (g.type == "forest") {
    r.checkKeys(n, key, {"type", "density", "seed", "size"});
    max_density = 0.5;
    default_density = 0.05;
  } else if (g.type == "city") {
    r.checkKeys(n, key, {"type", "density", "seed", "size"});
  } else if (g.type == "maze") {
    r.checkKeys(n, key, {"type", "density", "seed", "size", "cell"});
    default_density = 1.0;
    if (n["cell"]) g.cell = r.number(n["cell"], key + ".cell", 0.5, 100.0);
  } else {
    r.fail(n["type"], key + ".type", "unknown generator '" + g.type + "' (forest, city, maze)");
  }
  g.densities = {default_density};
  if (n["density"])
    g.densities = oneOrMany<double>(n["density"], key + ".density",
                                    [&](const YAML::Node& v, const std::string& k) {
                                      return r.number(v, k, 0.0, max_density);
                                    });
  g.seeds = {1};
  if (n["seed"])
    g.seeds = oneOrMany<long>(
        n["seed"], key + ".seed",
        [&](const YAML::Node& v, const std::string& k) { return r.integer(v, k, 0, 2147483647L); });
  if (g.densities.empty() || g.seeds.empty())
    r.fail(n, key, "density and seed lists must not be empty");
  if (n["size"]) {
    const Eigen::Vector3d s = r.vec3(n["size"], key + ".size");
    for (int i = 0; i < 3; ++i) {
      if (s[i] < 3.0 || s[i] > 10000.0)
        r.fail(n["size"], key + ".size", "each size must be in [3, 10000] m");
      g.size[i] = s[i];
    }
  }
  return g;
}

// scenarios: one file or a list, each found beside the sweep file or in the current directory.
void readScenarioFiles(const YamlReader& r, const YAML::Node& list,
                       const std::filesystem::path& file, SweepSpec& s) {
  if (!list.IsSequence() && !list.IsScalar())
    r.fail(list, "scenarios", "must be a list of scenario files");
  const auto written = oneOrMany<std::pair<std::string, std::string>>(
      list, "scenarios", [&](const YAML::Node& v, const std::string& k) {
        return std::make_pair(r.text(v, k), r.place(v, k));
      });
  for (const auto& [w, place] : written) {
    SweepScenarioFile f{w, resolveSweepScenarioPath(w, file), place};
    if (f.path.empty())
      throw InputError(
          file.string(), place,
          "scenario file not found: '" + w + "' (looked in " +
              (file.parent_path().empty() ? std::string(".") : file.parent_path().string()) +
              " and in the current directory)");
    s.scenarios.push_back(f);
  }
}

// vary: key -> list of values; `jobs` (the count so far) is multiplied by each list's length.
void readVariables(const YamlReader& r, const YAML::Node& vary, std::size_t jobs, SweepSpec& s) {
  r.requireMap(vary, "vary");
  std::set<std::string> seen;
  for (const auto& kv : vary) {
    SweepVariable v;
    v.key = kv.first.Scalar();
    const std::string key = "vary." + v.key;
    v.place = r.place(kv.first, key);
    // The keys --set takes: a.b.c, with list elements as vehicles[0].goal.
    if (!isScenarioKey(v.key, true))
      r.fail(kv.first, key, "not a scenario key (e.g. planner.name, vehicles[0].goal)");
    if (const std::string problem = overridePathProblem(v.key); !problem.empty())
      r.fail(kv.first, key, problem);
    if (!seen.insert(v.key).second) r.fail(kv.first, key, "listed twice");
    const YAML::Node values = kv.second;
    if (values.IsSequence()) {
      if (values.size() == 0) r.fail(values, key, "needs at least one value");
      for (const auto& x : values) v.values.push_back(overrideValue(x));
    } else if (values.IsScalar() && !values.Scalar().empty()) {
      v.values.push_back(values.Scalar());
    } else {
      r.fail(values, key, "must be a list of values, e.g. [astar, theta_star]");
    }
    jobs *= v.values.size();
    if (jobs > kMaxJobs) r.fail(values, key, "the sweep would have more than 1000000 jobs");
    s.vary.push_back(v);
  }
}

// output: video, the figure's metric and the varied key it is drawn against.
void readOutput(const YamlReader& r, const YAML::Node& o, SweepSpec& s) {
  r.checkKeys(o, "output", {"video", "figure", "figure_by"});
  if (o["video"]) s.video = r.boolean(o["video"], "output.video");
  if (o["figure"]) s.figure_metric = r.text(o["figure"], "output.figure");
  if (o["figure_by"]) {
    s.figure_by = r.text(o["figure_by"], "output.figure_by");
    bool varied = false;
    for (const auto& v : s.vary) varied = varied || v.key == s.figure_by;
    if (!varied)
      r.fail(o["figure_by"], "output.figure_by", "'" + s.figure_by + "' is not a key under vary:");
  }
}

// limits: a job's time limit and the grace before SIGKILL.
void readLimits(const YamlReader& r, const YAML::Node& l, SweepSpec& s) {
  r.checkKeys(l, "limits", {"job_timeout_s", "kill_grace_s"});
  if (l["job_timeout_s"])
    s.job_timeout_s = r.number(l["job_timeout_s"], "limits.job_timeout_s", 0.1, 1e7);
  if (l["kill_grace_s"])
    s.kill_grace_s = r.number(l["kill_grace_s"], "limits.kill_grace_s", 0.0, 600.0);
}

}  // namespace

std::filesystem::path resolveSweepScenarioPath(const std::string& written,
                                               const std::filesystem::path& sweep_file) {
  const std::filesystem::path p(written);
  std::error_code ec;
  if (p.is_absolute()) return std::filesystem::exists(p, ec) ? p : std::filesystem::path();
  const std::filesystem::path beside = sweep_file.parent_path() / p;
  if (std::filesystem::is_regular_file(beside, ec)) return beside.lexically_normal();
  if (std::filesystem::is_regular_file(p, ec)) return p.lexically_normal();
  return {};
}

SweepSpec loadSweepSpec(const std::filesystem::path& file) {
  return parseSweepSpec(readInputFile(file.string(), kMaxScenarioFileBytes, "sweep file"), file);
}

SweepSpec parseSweepSpec(const std::string& text, const std::filesystem::path& file) {
  const YamlReader r(file.string());
  const YAML::Node root = loadYamlDocument(text, file.string());
  if (!root.IsMap())
    throw InputError(file.string(), "", "a sweep file is a mapping (scenarios:, vary:, ...)");
  r.checkKeys(root, "", {"name", "scenarios", "generators", "vary", "set", "output", "limits"});

  SweepSpec s;
  s.file = file;
  s.name = root["name"] ? r.text(root["name"], "name") : file.stem().string();
  // The name becomes a folder (out/sweep-NAME): a path in it would write elsewhere.
  if (const std::string why = unsafeNameReason(s.name); !why.empty())
    r.fail(root["name"] ? root["name"] : root, "name",
           "'" + s.name + "' cannot name the sweep's folder: " + why);
  if (root["scenarios"]) readScenarioFiles(r, root["scenarios"], file, s);
  if (root["generators"]) {
    const YAML::Node list = root["generators"];
    if (!list.IsSequence())
      r.fail(list, "generators", "must be a list of {type: ..., density: ..., seed: ...}");
    for (std::size_t i = 0; i < list.size(); ++i)
      s.generators.push_back(readGenerator(r, list[i], "generators[" + std::to_string(i) + "]"));
  }
  if (s.scenarios.empty() && s.generators.empty())
    r.fail(root, "scenarios", "a sweep needs 'scenarios:' or 'generators:' (at least one)");

  std::size_t jobs = s.scenarios.size();
  for (const auto& g : s.generators) jobs += g.densities.size() * g.seeds.size();
  if (root["vary"]) readVariables(r, root["vary"], jobs, s);
  if (root["set"]) {
    flattenOverrides(r, root["set"], "", s.fixed);
    for (const auto& [k, value] : s.fixed)
      for (const auto& v : s.vary)
        if (v.key == k) r.fail(root["set"], "set." + k, "is also under vary:");
  }
  if (root["output"]) readOutput(r, root["output"], s);
  if (root["limits"]) readLimits(r, root["limits"], s);
  return s;
}

}  // namespace cosim
