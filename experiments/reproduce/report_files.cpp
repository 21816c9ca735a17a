#include "experiments/reproduce/report_files.h"

#include <cstdio>
#include <filesystem>

#include "core/atomic_file.h"
#include "experiments/reproduce/agreement_section.h"

namespace cosim::reproduce {

namespace {
const char* kQuickNote =
    "> **Quick run (`--quick`)**: fewer runs and smaller settings, a smoke test of the "
    "reproduction, not its result. Run without `--quick` for the numbers to compare.";
}  // namespace

std::string reportMarkdown(const Options& options, const Report& report) {
  std::string md = report.markdown;
  if (report.run_time_s >= 0) {
    // Appended piece by piece: GCC 12 warns (-Wrestrict, a false positive) on "..." + string&&.
    if (!md.empty() && md.back() != '\n') md += '\n';
    md += "\nRun time: ";
    md += fixed(report.run_time_s, 0);
    md += " s (wall clock, the whole reproduction).\n";
  }
  if (!options.quick) return md;
  // Under the title line if there is one, else at the top.
  const std::size_t title_end = md.rfind('#', 0) == 0 ? md.find('\n') : std::string::npos;
  if (title_end == std::string::npos) return std::string(kQuickNote) + "\n\n" + md;
  return md.substr(0, title_end + 1) + "\n" + kQuickNote + "\n" + md.substr(title_end + 1);
}

std::string reportJson(const std::string& name, const Options& options, const Report& report) {
  JsonObject doc;
  doc.add("experiment", name)
      .add("quick", options.quick)
      .add("seed", static_cast<double>(options.seed));
  if (report.run_time_s >= 0) doc.add("run_time_s", report.run_time_s);
  std::string agreement = "[";
  for (const std::string& line : agreementLines(report.markdown)) {
    if (agreement.size() > 1) agreement += ',';
    agreement += JsonObject::quote(line);
  }
  doc.raw("agreement", agreement + "]").addArray("rows", report.rows);
  return doc.str() + "\n";
}

std::string writeReportFiles(const std::string& name, const Options& options,
                             const Report& report) {
  const std::filesystem::path dir(options.out_dir);
  const std::string md = reportMarkdown(options, report);
  writeFileAtomically(dir / (name + ".json"), reportJson(name, options, report));
  writeFileAtomically(dir / (name + ".md"), md);
  return md;
}

std::string fmt(const char* printf_format, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, printf_format, v);
  return buf;
}

std::string fixed(double v, int decimals) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}

}  // namespace cosim::reproduce
