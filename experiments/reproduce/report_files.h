#pragma once
// The two files every reproduction writes (docs/reproductions.md): DIR/NAME.md, the report,
// and DIR/NAME.json, {"experiment": NAME, "quick": ..., "seed": ..., "rows": [...]}.
// A --quick run is a smoke test, not the reproduction's result, and both files say so.
#include <string>

#include "experiments/reproduce/reproduction.h"

namespace cosim::reproduce {

// The report as written to NAME.md: with --quick, a line under the title says it is a quick run;
// a timed run ends with its run time.
std::string reportMarkdown(const Options& options, const Report& report);

// One number for a report's tables, printf-style (fmt("%.2f", x)), or with `decimals` digits
// after the point.
std::string fmt(const char* printf_format, double v);
std::string fixed(double v, int decimals);

// NAME.json's text: {"experiment", "quick", "seed", "run_time_s" (if timed), "agreement" (the
// closing section's finding lines, agreementLines()), "rows"}.
std::string reportJson(const std::string& name, const Options& options, const Report& report);

// Writes both files into options.out_dir, each atomically; returns the markdown written.
std::string writeReportFiles(const std::string& name, const Options& options, const Report& report);

}  // namespace cosim::reproduce
