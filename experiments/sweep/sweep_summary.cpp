#include "experiments/sweep/sweep_summary.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>

#include "core/output_files.h"
#include "experiments/sweep/job_result.h"

namespace cosim {

bool isSeedKey(const std::string& key) {
  const std::string last = key.substr(key.rfind('.') == std::string::npos ? 0 : key.rfind('.') + 1);
  return last.size() >= 4 && last.compare(last.size() - 4, 4, "seed") == 0;
}

namespace {

// Numbers and booleans count; text (planner names, messages) does not.
bool numericValue(const std::string& s, double& v) {
  if (s == "true" || s == "false") {
    v = s == "true" ? 1.0 : 0.0;
    return true;
  }
  if (s.empty()) return false;
  char* end = nullptr;
  v = std::strtod(s.c_str(), &end);
  return *end == '\0' && std::isfinite(v);
}

std::string number(double v) {
  if (!std::isfinite(v)) return "";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

}  // namespace

SweepSummary summarizeSweep(const SweepTable& t) {
  SweepSummary s;
  std::vector<std::size_t> group_cols = {1};  // scenario
  s.group_columns = {"scenario"};
  std::size_t status_col = 0;
  const std::string ok = jobStatusName(JobStatus::Ok);  // the status column holds the names
  for (std::size_t c = 2; c < t.first_metric_column; ++c) {
    if (t.header[c] == "status") {
      status_col = c;
      continue;
    }
    if (isSeedKey(t.header[c])) continue;
    group_cols.push_back(c);
    s.group_columns.push_back(t.header[c]);
  }
  // A metric column is numeric if every ok row that has a value has a numeric one; parameters
  // echoed by the planner (planner_params.*) describe the job, not its outcome.
  std::vector<std::size_t> metric_cols;
  for (std::size_t c = t.first_metric_column; c < t.header.size(); ++c) {
    if (t.header[c].rfind("planner_params.", 0) == 0 || t.header[c] == "seed") continue;
    bool any = false, numeric = true;
    for (const auto& r : t.rows) {
      double v;
      if (r[status_col] != ok || r[c].empty()) continue;
      any = true;
      numeric = numeric && numericValue(r[c], v);
    }
    if (any && numeric) metric_cols.push_back(c);
  }

  std::map<std::vector<std::string>, std::vector<const std::vector<std::string>*>> groups;
  std::vector<std::vector<std::string>> order;
  for (const auto& r : t.rows) {
    std::vector<std::string> key;
    for (std::size_t c : group_cols) key.push_back(r[c]);
    auto& members = groups[key];
    if (members.empty()) order.push_back(key);
    members.push_back(&r);
  }
  for (const auto& key : order) {
    const auto& members = groups[key];
    std::vector<double> ok_rate;
    for (const auto* r : members) ok_rate.push_back((*r)[status_col] == ok ? 1.0 : 0.0);
    s.rows.push_back({key, "ok_rate", members.size(), describeSample(ok_rate)});
    for (std::size_t c : metric_cols) {
      std::vector<double> values;
      for (const auto* r : members) {
        double v;
        if ((*r)[status_col] == ok && numericValue((*r)[c], v)) values.push_back(v);
      }
      // A metric no ok job of the group has (all failed, or it does not apply) has no row.
      if (!values.empty())
        s.rows.push_back({key, t.header[c], members.size(), describeSample(values)});
    }
  }
  return s;
}

std::string sweepSummaryCsv(const SweepSummary& s) {
  std::string out;
  for (const auto& g : s.group_columns) out += csvField(g) + ",";
  out += "metric,jobs,n,mean,sd,median,ci95_low,ci95_high\n";
  for (const auto& r : s.rows) {
    for (const auto& g : r.group) out += csvField(g) + ",";
    out += csvField(r.metric) + "," + std::to_string(r.jobs) + "," + std::to_string(r.stats.n) +
           "," + number(r.stats.mean) + "," + number(r.stats.sd) + "," + number(r.stats.median) +
           "," + number(r.stats.ci95_low) + "," + number(r.stats.ci95_high) + "\n";
  }
  return out;
}

}  // namespace cosim
