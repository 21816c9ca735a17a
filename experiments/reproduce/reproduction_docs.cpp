#include "experiments/reproduce/reproduction_docs.h"

#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/input_error.h"

namespace cosim::reproduce {

namespace {

struct CommittedReport {
  std::string name;
  double run_time_s = 0;
  double seed = 0;
  std::vector<std::string> agreement;
};

// The keys the page quotes, checked: a quick run or an untimed one is not a result to quote.
CommittedReport readReport(const std::string& path, const std::string& text) {
  const nlohmann::json j = nlohmann::json::parse(text, nullptr, false);
  if (j.is_discarded() || !j.is_object()) throw InputError(path, "", "not a JSON object");
  auto need = [&](const char* key, bool ok) {
    if (!j.contains(key) || !ok)
      throw InputError(path, key,
                       "missing or of the wrong kind (docs/reproductions.md quotes "
                       "\"experiment\", \"quick\": false, \"seed\", \"run_time_s\" and "
                       "\"agreement\" of a full run)");
  };
  need("experiment", j.contains("experiment") && j["experiment"].is_string());
  need("quick", j.contains("quick") && j["quick"] == false);
  need("seed", j.contains("seed") && j["seed"].is_number());
  need("run_time_s", j.contains("run_time_s") && j["run_time_s"].is_number());
  need("agreement",
       j.contains("agreement") && j["agreement"].is_array() && !j["agreement"].empty());
  CommittedReport r;
  r.name = j["experiment"].get<std::string>();
  r.run_time_s = j["run_time_s"].get<double>();
  r.seed = j["seed"].get<double>();
  for (const auto& line : j["agreement"]) {
    if (!line.is_string()) throw InputError(path, "agreement", "holds a non-string line");
    r.agreement.push_back(line.get<std::string>());
  }
  return r;
}

std::string seconds(double s) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.0f s", s);
  return buf;
}

// Where the verdict list starts.
const char* const kVerdictsAnchor = "\nVerdicts of the full runs";

std::string beginMarker(const std::string& path) {
  return "<!-- generated from " + path + ": begin -->\n";
}
std::string endMarker(const std::string& path) {
  return "<!-- generated from " + path + ": end -->\n";
}

// Puts the block in place of the old one, the hand-written item, or at the list's end.
void placeBlock(std::string& doc, const std::string& path, const std::string& name,
                const std::string& block) {
  const std::string begin = beginMarker(path), end = endMarker(path);
  if (const std::size_t b = doc.find(begin); b != std::string::npos) {
    const std::size_t e = doc.find(end, b);
    if (e == std::string::npos) throw InputError("docs/reproductions.md", path, "block never ends");
    doc.replace(b, e + end.size() - b, block);
    return;
  }
  // Only in the verdict list: the page's earlier sections have items named after reproductions too.
  const std::size_t list = doc.find(kVerdictsAnchor);
  if (list == std::string::npos)
    throw InputError("docs/reproductions.md", "verdicts",
                     std::string("no line starting \"") + (kVerdictsAnchor + 1) + "\"");
  if (const std::size_t item = doc.find("\n- **" + name + "**", list); item != std::string::npos) {
    std::size_t stop = doc.find('\n', item + 1);
    while (stop != std::string::npos && doc.compare(stop + 1, 2, "  ") == 0)
      stop = doc.find('\n', stop + 1);
    doc.replace(item + 1, (stop == std::string::npos ? doc.size() : stop + 1) - item - 1, block);
    return;
  }
  const std::size_t next = doc.find("\n## Other reproductions", list);
  if (next == std::string::npos)
    throw InputError("docs/reproductions.md", "verdicts", "no \"## Other reproductions\" heading");
  doc.insert(next, block);
}

// The run-time table row "| `NAME` | rebuilds | maps | full run | quick |": its full-run cell.
void placeRunTime(std::string& doc, const std::string& name, double run_time_s) {
  const std::size_t row = doc.find("\n| `" + name + "` |");
  if (row == std::string::npos)
    throw InputError("docs/reproductions.md", name, "no row in the run-time table");
  const std::size_t eol = doc.find('\n', row + 1);
  std::string line = doc.substr(row + 1, eol - row - 1);
  std::vector<std::size_t> bars;
  for (std::size_t i = 0; i < line.size(); ++i)
    if (line[i] == '|') bars.push_back(i);
  if (bars.size() != 6)
    throw InputError("docs/reproductions.md", name, "its table row does not have 5 cells");
  std::string cell = " ";  // built apart: GCC 12 warns (-Wrestrict) on " " + string&&
  cell += seconds(run_time_s);
  cell += ' ';
  line.replace(bars[3] + 1, bars[4] - bars[3] - 1, cell);
  doc.replace(row + 1, eol - row - 1, line);
}

}  // namespace

std::string reproductionVerdictBlock(const std::string& json_path, const std::string& json_text) {
  const CommittedReport r = readReport(json_path, json_text);
  std::string block = beginMarker(json_path) + "- **" + r.name + "** (full run, seed " +
                      std::to_string(static_cast<long long>(r.seed)) + ", " +
                      seconds(r.run_time_s) + "; the report's closing section):\n";
  for (const std::string& line : r.agreement) block += "  - " + line + "\n";
  return block + endMarker(json_path);
}

std::string reproductionDocsWithReports(std::string doc,
                                        const std::map<std::string, std::string>& reports) {
  for (const auto& [path, text] : reports) {
    const CommittedReport r = readReport(path, text);
    placeBlock(doc, path, r.name, reproductionVerdictBlock(path, text));
    placeRunTime(doc, r.name, r.run_time_s);
  }
  return doc;
}

}  // namespace cosim::reproduce
