#include "experiments/sweep/sweep_results_table.h"

#include <map>
#include <nlohmann/json.hpp>
#include <set>

#include "core/input_error.h"
#include "core/json_flatten.h"
#include "core/json_reading.h"
#include "core/json_writer.h"
#include "core/output_files.h"
#include "experiments/sweep/job_result.h"
#include "experiments/sweep/sweep_runner.h"

namespace cosim {

namespace {

using Fields = FlatJson;

// A job's metrics.json as columns (key paths). A single vehicle's entry under "vehicles" repeats
// the top-level metrics, so it gives no columns; a null (a non-finite number) is an empty cell.
Fields readMetrics(const std::filesystem::path& file) {
  std::error_code ec;
  if (!std::filesystem::exists(file, ec)) return {};
  try {
    nlohmann::ordered_json metrics = readJsonFile(file);
    if (metrics.is_object() && metrics.contains("vehicles") && metrics["vehicles"].is_array() &&
        metrics["vehicles"].size() == 1)
      metrics.erase("vehicles");
    return flattenJsonDocument(metrics, "");
  } catch (const InputError&) {
    return {};  // unreadable: the row keeps its status, without metrics
  }
}

}  // namespace

SweepTable mergeSweepResults(const SweepSpec& spec, const std::vector<SweepJob>& jobs,
                             const std::filesystem::path& out_dir) {
  SweepTable t;
  t.header = {"job", "scenario"};
  for (const auto& v : spec.vary) t.header.push_back(v.key);
  t.header.push_back("status");
  t.first_metric_column = t.header.size();
  std::map<std::string, std::size_t> fixed_columns;
  for (std::size_t i = 0; i < t.header.size(); ++i) fixed_columns[t.header[i]] = i;

  struct Row {
    std::vector<std::string> fixed;
    Fields metrics;
    std::string wall;
  };
  std::vector<Row> rows;
  std::vector<std::string> metric_names;
  std::map<std::string, std::size_t> metric_index;
  std::set<std::string> builds;
  for (const auto& job : jobs) {
    const auto dir = sweepJobDir(out_dir, job, jobs.size());
    const auto result = readJobResult(dir);
    if (!result || result->fingerprint != job.fingerprint || result->job != job.id) {
      ++t.unfinished;
      continue;
    }
    builds.insert(result->program_build);
    Row row;
    row.fixed = {std::to_string(job.id), job.scenario};
    row.fixed.insert(row.fixed.end(), job.values.begin(), job.values.end());
    row.fixed.push_back(jobStatusName(result->status));
    for (auto& [name, value] : readMetrics(dir / "metrics.json")) {
      if (fixed_columns.count(name)) continue;
      if (metric_index.emplace(name, metric_names.size()).second) metric_names.push_back(name);
      row.metrics.emplace_back(name, value);
    }
    row.wall = JsonObject::number(result->wall_time_s);
    rows.push_back(std::move(row));
  }
  t.program_builds = builds.size();
  for (const auto& m : metric_names) t.header.push_back(m);
  t.header.push_back("job_wall_time_s");
  for (auto& r : rows) {
    std::vector<std::string> cells = r.fixed;
    cells.resize(t.header.size());
    for (const auto& [name, value] : r.metrics)
      cells[t.first_metric_column + metric_index[name]] = value;
    cells.back() = r.wall;
    t.rows.push_back(std::move(cells));
  }
  return t;
}

std::string sweepTableCsv(const SweepTable& table) {
  std::string s;
  const auto line = [&s](const std::vector<std::string>& cells) {
    for (std::size_t i = 0; i < cells.size(); ++i) {
      if (i) s += ",";
      s += csvField(cells[i]);
    }
    s += "\n";
  };
  line(table.header);
  for (const auto& r : table.rows) line(r);
  return s;
}

}  // namespace cosim
