// index.html opened in headless Chromium: every video and image loads.
#include "render/html_report.h"

#include <gtest/gtest.h>

#include "render/run_outputs.h"
#include "render_test_scene.h"
#include "run/run_evaluation.h"

using namespace cosim;
using namespace cosim::test;

namespace {

std::string chromium() {
  for (const char* p : {"/usr/bin/chromium", "/usr/bin/chromium-browser", "/usr/bin/google-chrome"})
    if (std::filesystem::exists(p)) return p;
  return "";
}

// The DOM after scripts ran, as Chromium saw it (empty if Chromium failed).
std::string dumpDom(const std::string& browser, const std::filesystem::path& page) {
  const auto dir = page.parent_path();
  const std::filesystem::path profile = dir / "chromium-profile", out = dir / "dom.html";
  const std::string cmd =
      browser +
      " --headless --no-sandbox --disable-gpu --disable-dev-shm-usage --no-first-run"
      " --disable-background-networking --disable-component-update --disable-sync"
      " --autoplay-policy=no-user-gesture-required --user-data-dir=" +
      profile.string() + " --virtual-time-budget=20000 --dump-dom file://" + page.string() + " > " +
      out.string() + " 2> /dev/null";
  if (std::system(cmd.c_str()) != 0) return "";
  return slurp(out);
}

}  // namespace

TEST(HtmlReport, RunReportLoadsEveryVideoAndFigureInHeadlessChromium) {
  const std::string browser = chromium();
  if (browser.empty())
    GTEST_SKIP()
        << "Chromium is not installed (Debian package 'chromium'); the report cannot be checked";
  const auto dir = makeFreshDir("report");
  Scenario s = renderTestScenario(320, 180);
  s.render.fps = 5;
  s.render.cameras = {CameraKind::Top};
  const RunLog log = straightFlightLog(1.0);
  const WorldModel world = WorldModel::build(s);
  RunRenderRequest request;
  const RunRecord record = recordOfLog(s, log, world);
  const RenderedRun rendered = renderRunOutputs(s, record, dir, request);
  EXPECT_EQ(rendered.videos, (std::vector<std::string>{"video.mp4", "video_top.mp4"}));
  writeRunReport(dir, s, record, JsonObject().add("reached_goal", true).add("rmse_m", 0.0123),
                 rendered);
  const std::string dom = dumpDom(browser, dir / "index.html");
  ASSERT_FALSE(dom.empty()) << "Chromium did not run";
  EXPECT_NE(dom.find("data-media=\"loaded\""), std::string::npos) << dom.substr(0, 3000);
  EXPECT_NE(dom.find("1.23 cm"), std::string::npos);  // the metrics table

  // The check can fail: with a figure missing, the page reports it.
  std::filesystem::remove(dir / "figures" / "side.png");
  const std::string broken = dumpDom(browser, dir / "index.html");
  EXPECT_NE(broken.find("data-media=\"failed: figures/side.png\""), std::string::npos)
      << broken.substr(0, 3000);
  std::filesystem::remove_all(dir);
}

TEST(HtmlReport, MetricTablesShowRoundedNumbersWithUnitsAndWrapLongNames) {
  // metrics.json keeps every digit; the page's tables (not only its cards) round them and give
  // the unit, and long names and values wrap instead of widening the page past 1280 px.
  const auto dir = makeFreshDir("report-numbers");
  HtmlReport report;
  report.title = "numbers";
  report.metrics = {{"flight_time_s", "29.23000000001274"},
                    {"min_clearance_m", "0.3860903991925237"},
                    {"planner_counters.expansions", "2676.0"},
                    {"trajectory_counters.peak_thrust_accel", "10.003260550497535"},
                    {"vehicles[0].name", "uav1"},
                    {"vehicles[0].rmse_m", "0.04502681105474928"}};
  writeHtmlReport(dir, report);
  const std::string page = slurp(dir / "index.html");
  for (const char* raw : {"0.3860903991925237", "29.23000000001274", "10.003260550497535",
                          "0.04502681105474928", "2676.0"})
    EXPECT_EQ(page.find(raw), std::string::npos) << raw;
  for (const char* shown : {">38.6 cm<", ">29.23 s<", ">2676<", ">10.0<", ">4.50 cm<"})
    EXPECT_NE(page.find(shown), std::string::npos) << shown;
  EXPECT_NE(page.find("overflow-wrap: anywhere"), std::string::npos);
  EXPECT_NE(page.find(".tables > div { min-width: 0; }"), std::string::npos);
  std::filesystem::remove_all(dir);
}
