// Names are data: vehicles named with each output format's special characters (HTML, JSON inside
// <script>, XML, CSV, gnuplot strings) and a scenario file whose name holds them too, a control
// byte and a byte that is not UTF-8, run through every output of a short flight; then each output
// is opened as its reader would: the pages in headless Chromium (their data parsed and their
// scripts run), every SVG by an XML parser, the CSVs and JSON read back to the same names.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "core/csv_text.h"
#include "render/viewer_page.h"
#include "tests/support/cosim_command.h"

using namespace cosim::test;

namespace {

namespace fs = std::filesystem;

// Vehicle names take printable ASCII but space and '/': one per format's specials.
const std::vector<std::string> kNames = {
    "<!--<script>",      // HTML comment and script opener: the viewer's data ended the page
    "q\"x'y]]>",         // quotes; "]]>" may not stand in XML text (error.svg was malformed)
    "a&b\\,'@^_{}%s~<",  // entity, backslash, CSV comma, gnuplot's enhanced-text specials
};

// The scenario file's name: the specials, a space, an escape byte and a byte that is not UTF-8.
const std::string kScenarioName = "s <!--<script> q\"x'y]]> a&b\\,@%s\x1b[31m\xff.yaml";

std::string shellQuoted(const std::string& s) {
  std::string q = "'";
  for (const char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

// Three cf2 hops of a metre, side by side, over their given waypoints (no planner).
std::string scenarioText() {
  std::ostringstream y;
  y << "world: {bounds: {min: [0, 0, 0], max: [8, 8, 3]}}\nvehicles:\n";
  for (std::size_t i = 0; i < kNames.size(); ++i)
    y << "  - {name: " << nlohmann::json(kNames[i]).dump() << ", model: cf2, start: [2, "
      << 2 + 2 * i << ", 1], goal: [3, " << 2 + 2 * i << ", 1]}\n";
  y << "sim: {max_time: 6}\nrender: {width: 320, height: 240}\n";
  return y.str();
}

std::string chromium() {
  for (const char* p : {"/usr/bin/chromium", "/usr/bin/chromium-browser", "/usr/bin/google-chrome"})
    if (fs::exists(p)) return p;
  return "";
}

// The DOM after the page's scripts ran (software WebGL, no network), or "" if Chromium failed.
std::string dumpDom(const std::string& browser, const fs::path& page, const std::string& fragment) {
  const fs::path out = page.parent_path() / "dom.html";
  const std::string cmd =
      browser +
      " --headless --no-sandbox --use-angle=swiftshader --enable-unsafe-swiftshader"
      " --disable-dev-shm-usage --no-first-run --disable-background-networking"
      " --disable-component-update --disable-sync --host-resolver-rules=\"MAP * ~NOTFOUND\""
      " --user-data-dir=" +
      (page.parent_path() / "chromium-profile").string() +
      " --window-size=640,360 --virtual-time-budget=8000 --dump-dom 'file://" + page.string() +
      fragment + "' > " + out.string() + " 2> /dev/null";
  if (std::system(cmd.c_str()) != 0) return "";
  std::ifstream in(out);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// The records of a CSV cosim wrote, each split as RFC 4180 says; a failure for a malformed one.
std::vector<std::vector<std::string>> readCsv(const fs::path& file) {
  std::ifstream in(file);
  std::vector<std::vector<std::string>> rows;
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> fields;
    EXPECT_TRUE(cosim::splitCsvRecord(line, fields)) << file << ": " << line;
    rows.push_back(fields);
  }
  return rows;
}

std::set<std::string> columnValues(const std::vector<std::vector<std::string>>& rows,
                                   const std::string& name) {
  std::set<std::string> values;
  const auto at = std::find(rows.at(0).begin(), rows.at(0).end(), name) - rows.at(0).begin();
  for (std::size_t i = 1; i < rows.size(); ++i) values.insert(rows[i].at(at));
  return values;
}

bool hasControlBytes(const std::string& text) {
  return std::any_of(text.begin(), text.end(),
                     [](unsigned char c) { return (c < 0x20 && c != '\n') || c == 0x7f; });
}

// One run serves every test: made once, removed at the end.
class NamesAreData : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = makeFreshDir("names-are-data");
    const fs::path scenario = dir_ / kScenarioName;
    std::ofstream(scenario) << scenarioText();
    run_ = dir_ / "run";
    result_ =
        runCosim("run " + shellQuoted(scenario.string()) + " --no-video --out " + run_.string());
  }
  static void TearDownTestSuite() { fs::remove_all(dir_); }
  static fs::path dir_, run_;
  static CommandResult result_;
};

fs::path NamesAreData::dir_, NamesAreData::run_;
CommandResult NamesAreData::result_;

TEST_F(NamesAreData, TheTerminalGetsNoControlBytesAndTheJsonAndCsvReadBack) {
  ASSERT_EQ(result_.status, 0) << result_.err;
  EXPECT_FALSE(hasControlBytes(result_.out)) << result_.out;
  EXPECT_FALSE(hasControlBytes(result_.err)) << result_.err;

  const nlohmann::json metrics = nlohmann::json::parse(slurp(run_ / "metrics.json"));
  ASSERT_EQ(metrics.at("vehicles").size(), kNames.size());
  for (std::size_t i = 0; i < kNames.size(); ++i)
    EXPECT_EQ(metrics["vehicles"][i].at("name").get<std::string>(), kNames[i]);
  EXPECT_TRUE(nlohmann::json::parse(slurp(run_ / "run.json")).at("scenario_file").is_string());

  const std::set<std::string> names(kNames.begin(), kNames.end());
  EXPECT_EQ(columnValues(readCsv(run_ / "timeseries.csv"), "vehicle"), names);
  EXPECT_EQ(columnValues(readCsv(run_ / "path.csv"), "vehicle"), names);

  // The run folder renders again with these names.
  const CommandResult again =
      runCosim("render " + run_.string() + " --out " + (dir_ / "frame.png").string() + " --quiet");
  EXPECT_EQ(again.status, 0) << again.err;
}

TEST_F(NamesAreData, EverySvgIsWellFormedXmlAndShowsTheNames) {
  ASSERT_EQ(result_.status, 0) << result_.err;
  std::string files;
  int count = 0;
  for (const auto& f : fs::directory_iterator(run_ / "figures"))
    if (f.path().extension() == ".svg") {
      files.append(" ").append(shellQuoted(f.path().string()));
      ++count;
    }
  EXPECT_EQ(count, 3) << "error, top and side";
  // Python's expat parser: the exit status says whether every file is well-formed XML.
  const std::string check =
      "python3 -c 'import sys, xml.etree.ElementTree as E\nfor f in sys.argv[1:]: E.parse(f)'" +
      files;
  EXPECT_EQ(std::system(check.c_str()), 0) << "an SVG is not well-formed XML";
  // gnuplot escaped '<' and '&'; '>' after "]]" became &gt;. The key names each vehicle.
  const std::string error = slurp(run_ / "figures" / "error.svg");
  EXPECT_NE(error.find("&lt;!--&lt;script>: RMSE"), std::string::npos);
  EXPECT_NE(error.find("q\"x'y]]&gt;: RMSE"), std::string::npos);
  EXPECT_NE(error.find("a&amp;b\\,'@^_{}%s~&lt;: RMSE"), std::string::npos);
}

TEST_F(NamesAreData, ThePagesParseTheirDataAndRunTheirScriptsInChromium) {
  ASSERT_EQ(result_.status, 0) << result_.err;
  const std::string browser = chromium();
  if (browser.empty()) GTEST_SKIP() << "Chromium is not installed (Debian package 'chromium')";

  // index.html: its load check ran (a script after the names), and the names are text.
  const std::string index = dumpDom(browser, run_ / "index.html", "");
  ASSERT_FALSE(index.empty()) << "Chromium did not run";
  EXPECT_NE(index.find("data-media=\"loaded\""), std::string::npos) << index.substr(0, 2000);
  EXPECT_NE(index.find("<th>&lt;!--&lt;script&gt;</th>"), std::string::npos);
  EXPECT_NE(index.find("<th>q\"x'y]]&gt;</th>"), std::string::npos);

  // viewer.html: the data parsed and the scripts ran (the page marks itself ready), the names
  // are the follow menu's options, and a malformed fragment (%ZZ threw URIError) is ignored.
  if (!cosim::loadThreeJs().missing.empty()) GTEST_SKIP() << cosim::loadThreeJs().missing;
  const std::string viewer = dumpDom(browser, run_ / "viewer.html", "#vehicle=%ZZ&t=1");
  ASSERT_FALSE(viewer.empty()) << "Chromium did not run";
  EXPECT_NE(viewer.find("data-viewer=\"ready\""), std::string::npos) << viewer.substr(0, 2000);
  EXPECT_NE(viewer.find("data-t=\"1.000\""), std::string::npos) << "the rest of the fragment";
  EXPECT_NE(viewer.find(">&lt;!--&lt;script&gt;</option>"), std::string::npos);
  EXPECT_NE(viewer.find(">q\"x'y]]&gt;</option>"), std::string::npos);
  EXPECT_NE(viewer.find(">a&amp;b\\,'@^_{}%s~&lt;</option>"), std::string::npos);
}

}  // namespace
