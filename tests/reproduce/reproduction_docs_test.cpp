// docs/reproductions.md's verdicts and full-run times are the committed reports' own
// (experiments/reproduce/results/NAME.json): the page is compared with what the generator makes
// of them, and COSIM_UPDATE_REPRODUCTION_DOCS=1 rewrites it from them.
#include "experiments/reproduce/reproduction_docs.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include "core/input_error.h"

namespace cosim::reproduce {
namespace {

namespace fs = std::filesystem;

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

const std::string kDoc =
    "| name | rebuilds | maps | full run | quick |\n|---|---|---|---|---|\n"
    "| `seed9-x` | Tab. 1 | map | 630 s | 2 s |\n\n- **seed9-x**: how it was rebuilt.\n\n"
    "Verdicts of the full runs:\n\n"
    "- **seed9-x**: agrees that it is 17 cells ahead\n  (630 s).\n"
    "- **seed9-y**: hand-written, kept.\n\n## Other reproductions\n";

const std::string kReport =
    R"({"experiment": "seed9-x", "quick": false, "seed": 1, "run_time_s": 55.6,
        "agreement": ["A: **agrees** (10 cells).", "B: **differs** (2), because C."],
        "rows": []})";

TEST(ReproductionDocs, ReplacesTheHandWrittenVerdictAndRunTimeWithTheReports) {
  const std::string doc = reproductionDocsWithReports(kDoc, {{"results/seed9-x.json", kReport}});
  EXPECT_NE(doc.find("| `seed9-x` | Tab. 1 | map | 56 s | 2 s |"), std::string::npos) << doc;
  EXPECT_NE(doc.find("<!-- generated from results/seed9-x.json: begin -->\n"
                     "- **seed9-x** (full run, seed 1, 56 s; the report's closing section):\n"
                     "  - A: **agrees** (10 cells).\n  - B: **differs** (2), because C.\n"
                     "<!-- generated from results/seed9-x.json: end -->\n"
                     "- **seed9-y**: hand-written, kept.\n"),
            std::string::npos)
      << doc;
  EXPECT_EQ(doc.find("17 cells"), std::string::npos) << doc;
  EXPECT_NE(doc.find("- **seed9-x**: how it was rebuilt.\n"), std::string::npos) << doc;
  // A second pass replaces the block by itself: the page is a fixed point.
  EXPECT_EQ(reproductionDocsWithReports(doc, {{"results/seed9-x.json", kReport}}), doc);
}

TEST(ReproductionDocs, RefusesAQuickRunOrOneWithoutItsAgreementLines) {
  std::string quick = kReport;
  quick.replace(quick.find("\"quick\": false"), 14, "\"quick\": true");
  EXPECT_THROW(reproductionVerdictBlock("r.json", quick), InputError);
  std::string bare = kReport;
  bare.replace(bare.find("\"agreement\""), 11, "\"findings\"");
  try {
    reproductionVerdictBlock("r.json", bare);
    FAIL() << "accepted a report without \"agreement\"";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("r.json"), std::string::npos) << e.what();
  }
}

TEST(ReproductionDocs, PageQuotesTheCommittedReports) {
  const fs::path root(COSIM_SOURCE_DIR);
  const fs::path page = root / "docs/reproductions.md";
  std::map<std::string, std::string> reports;
  for (const auto& entry : fs::directory_iterator(root / kCommittedReportsDir))
    if (entry.path().extension() == ".json")
      reports[std::string(kCommittedReportsDir) + "/" + entry.path().filename().string()] =
          slurp(entry.path());
  ASSERT_FALSE(reports.empty()) << "no committed reports in " << kCommittedReportsDir;
  const std::string doc = slurp(page);
  const std::string expected = reproductionDocsWithReports(doc, reports);
  if (std::getenv("COSIM_UPDATE_REPRODUCTION_DOCS"))
    std::ofstream(page, std::ios::binary) << expected;
  EXPECT_EQ(doc, expected) << "docs/reproductions.md differs from the committed reports (rewrite "
                              "it: COSIM_UPDATE_REPRODUCTION_DOCS=1 ctest -R ReproductionDocs)";
}

}  // namespace
}  // namespace cosim::reproduce
