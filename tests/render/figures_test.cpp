// Figures through gnuplot: a run's error/top/side figures and comparison charts from a CSV.
#include "render/figures.h"

#include <gtest/gtest.h>

#include <fstream>

#include "core/input_error.h"
#include "render/comparison_chart.h"
#include "render/gnuplot.h"
#include "render/overlay_palette.h"
#include "render_test_scene.h"
#include "run/run_evaluation.h"

using namespace cosim;
using namespace cosim::test;

namespace {

// Width and height from a PNG's IHDR chunk.
std::pair<int, int> pngSize(const std::filesystem::path& p) {
  const std::string b = slurp(p);
  if (b.size() < 24 || b.substr(1, 3) != "PNG") return {0, 0};
  const auto be32 = [&](std::size_t at) {
    return (static_cast<unsigned char>(b[at]) << 24) |
           (static_cast<unsigned char>(b[at + 1]) << 16) |
           (static_cast<unsigned char>(b[at + 2]) << 8) | static_cast<unsigned char>(b[at + 3]);
  };
  return {be32(16), be32(20)};
}

}  // namespace

TEST(Figures, RunFiguresAreWrittenAsPngAndSvgWithTheirContent) {
  const auto dir = makeFreshDir("figures");
  const Scenario s = renderTestScenario();
  const RunLog log = straightFlightLog(3.0, 0.25);
  const std::vector<std::string> names =
      writeRunFigures(s, recordOfLog(s, log, nullptr), dir / "figures");
  EXPECT_EQ(names, (std::vector<std::string>{"error", "top", "side"}));
  EXPECT_EQ(pngSize(dir / "figures" / "error.png"), std::make_pair(1000, 480));
  // Equal axes over the data (a flight 14 m along x, 2 m along y, with margins): a canvas half
  // as tall as wide.
  EXPECT_EQ(pngSize(dir / "figures" / "top.png"), std::make_pair(1000, 500));
  EXPECT_EQ(pngSize(dir / "figures" / "side.png"), std::make_pair(1000, 560));
  const std::string top = slurp(dir / "figures" / "top.svg");
  EXPECT_NE(top.find("<svg"), std::string::npos);
  EXPECT_NE(top.find("Top view"), std::string::npos);
  EXPECT_NE(top.find("planned path"), std::string::npos);
  EXPECT_NE(top.find("reference trajectory"), std::string::npos);
  // The colour bar says what the colour measures (a minimum-snap flight: its trajectory).
  EXPECT_NE(top.find("error to the reference trajectory [m]"), std::string::npos);
  // The error figure names the RMSE of the synthetic lag 0.25 sin(pi k/300) over its 301
  // samples: 0.25 sqrt(150/301) = 0.176 m, and its maximum 0.25 m.
  const std::string error = slurp(dir / "figures" / "error.svg");
  EXPECT_NE(error.find("RMSE 0.176 m, max 0.25 m"), std::string::npos);
  // Nothing but the six figures is left in the folder.
  int entries = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir / "figures"))
    ++entries;
  EXPECT_EQ(entries, 6);
  std::filesystem::remove_all(dir);
}

TEST(Figures, ComparisonChartWithNumericXIsALinePerGroupAveragedOverRepeats) {
  const auto dir = makeFreshDir("chart_lines");
  std::ofstream(dir / "results.csv")
      << "job,planner.name,resolution,planning_time_ms,status\n"
         "1,astar,0.5,10,ok\n2,astar,0.5,14,ok\n3,astar,1.0,4,ok\n"
         "4,theta_star,0.5,20,ok\n5,theta_star,1.0,7,ok\n6,theta_star,1.0,,failed\n";
  writeComparisonChart(dir / "results.csv", "resolution", "planning_time_ms", "planner.name",
                       dir / "time");
  EXPECT_EQ(pngSize(dir / "time.png"), std::make_pair(900, 500));
  const std::string svg = slurp(dir / "time.svg");
  EXPECT_NE(svg.find(">astar<"), std::string::npos);
  EXPECT_NE(svg.find(">theta_star<"), std::string::npos);
  std::filesystem::remove_all(dir);
}

TEST(Figures, ComparisonChartWithCategoricalXIsBars) {
  const auto dir = makeFreshDir("chart_bars");
  std::ofstream(dir / "results.csv")
      << "planner,scenario,rmse_m\nastar,forest,0.1\nrrt_star,forest,0.2\n"
         "astar,canyon,0.15\nrrt_star,canyon,0.3\n";
  writeComparisonChart(dir / "results.csv", "planner", "rmse_m", "scenario", dir / "rmse");
  const std::string svg = slurp(dir / "rmse.svg");
  EXPECT_NE(svg.find(">forest<"), std::string::npos);
  EXPECT_NE(svg.find(">canyon<"), std::string::npos);
  EXPECT_NE(svg.find(">rrt_star<"), std::string::npos);  // a category on the x axis
  EXPECT_GT(std::filesystem::file_size(dir / "rmse.png"), 5000u);
  std::filesystem::remove_all(dir);
}

TEST(Figures, ComparisonChartNamesAMissingColumn) {
  const auto dir = makeFreshDir("chart_bad");
  std::ofstream(dir / "results.csv") << "planner,rmse_m\nastar,0.1\n";
  try {
    writeComparisonChart(dir / "results.csv", "planner", "max_error_m", "", dir / "x");
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("max_error_m"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(std::filesystem::exists(dir / "x.png"));
  std::filesystem::remove_all(dir);
}

TEST(Figures, TeamPathFiguresShowFlownPathsAndTheirPlansOnlyWhenAsked) {
  const auto dir = makeFreshDir("team_figures");
  Scenario s = renderTestScenario();
  s.vehicles.push_back(s.vehicles[0]);
  s.vehicles[1].name = "uav2";
  RunLog log = straightFlightLog(3.0, 0.25);
  log.vehicles.push_back(log.vehicles[0]);
  log.vehicles[1].name = "uav2";
  writeRunFigures(s, recordOfLog(s, log, nullptr), dir / "flown");
  const std::string flown = slurp(dir / "flown" / "top.svg");
  // A grid plan's right angles are not drawn; the key names each kind of line once.
  EXPECT_EQ(flown.find("planned path"), std::string::npos);
  EXPECT_EQ(flown.find(">reference trajectory<"), std::string::npos);  // the key's entry
  EXPECT_NE(flown.find("Top view: flown paths"), std::string::npos);
  // Each member in its own colour, not by error (all trails were one purple).
  EXPECT_NE(flown.find("flown paths (one colour each)"), std::string::npos);
  EXPECT_EQ(flown.find("tracking error"), std::string::npos);
  EXPECT_EQ(flown.find("uav2"), std::string::npos);
  s.render.team_plans = true;
  writeRunFigures(s, recordOfLog(s, log, nullptr), dir / "plans");
  const std::string plans = slurp(dir / "plans" / "top.svg");
  EXPECT_NE(plans.find("planned paths (one colour each)"), std::string::npos);
  EXPECT_NE(plans.find(">reference trajectories<"), std::string::npos);
  EXPECT_NE(plans.find("Top view: planned vs flown path"), std::string::npos);
  // The error on demand (render.team_error): the flown paths coloured by it, with its bar.
  s.render.team_error = true;
  writeRunFigures(s, recordOfLog(s, log, nullptr), dir / "error");
  const std::string error = slurp(dir / "error" / "top.svg");
  EXPECT_NE(error.find("flown paths (colour: tracking error)"), std::string::npos);
  EXPECT_NE(error.find("error to the reference trajectory [m]"), std::string::npos);
  std::filesystem::remove_all(dir);
}

// gnuplot's svg terminal escapes '<' and '&' in text but not '>': a vehicle named q"x'y]]> made
// "]]>" in character data, which XML forbids. CDATA sections keep their own "]]>".
TEST(Figures, SvgTextIsMadeWellFormedAroundCdataSections) {
  EXPECT_EQ(wellFormedSvgText("<text>q\"x'y]]> a&amp;b</text>"),
            "<text>q\"x'y]]&gt; a&amp;b</text>");
  EXPECT_EQ(wellFormedSvgText("<script><![CDATA[ if (a[0] > 1) {} ]]></script><text>]]></text>"),
            "<script><![CDATA[ if (a[0] > 1) {} ]]></script><text>]]&gt;</text>");
  EXPECT_EQ(wellFormedSvgText("<svg>no specials</svg>"), "<svg>no specials</svg>");
}

// A gnuplot string literal: single quotes doubled, everything else as itself but control bytes
// and bytes that are not UTF-8 (a line break would end the script's line).
TEST(Figures, GnuplotStringsQuoteAndEscapeTheUsersBytes) {
  EXPECT_EQ(gnuplotString("q\"x'y \\ @^_{}&"), "'q\"x''y \\ @^_{}&'");
  EXPECT_EQ(gnuplotString("a\nb\xff"), "'a\\x0ab\\xff'");
}

namespace {

// "rgb(r, g, b)" as gnuplot's SVG writes a line's colour: each number three characters wide.
std::string svgColour(const Eigen::Vector3f& c) {
  const auto byte = [](float x) { return static_cast<int>(std::lround(x * 255.0f)); };
  char text[32];
  std::snprintf(text, sizeof text, "rgb(%3d, %3d, %3d)", byte(c.x()), byte(c.y()), byte(c.z()));
  return text;
}

}  // namespace

TEST(Figures, ATeamsTrailsAreEachInTheirVehiclesColour) {
  const auto dir = makeFreshDir("team_colours");
  Scenario s = renderTestScenario();
  RunLog log = straightFlightLog(2.0, 0.25);
  const VehicleSpec spec = s.vehicles[0];
  const VehicleLog first = log.vehicles[0];
  s.vehicles.clear();
  log.vehicles.clear();
  for (int a = 0; a < 32; ++a) {
    s.vehicles.push_back(spec);
    // Built piece by piece: GCC 12's -Wstringop-overflow misfires on "q" + std::to_string.
    std::string name = "q";
    name += std::to_string(a);
    s.vehicles.back().name = name;
    VehicleLog v = first;
    v.name = s.vehicles.back().name;
    const Eigen::Vector3d shift(0, 0.4 * a, 0);
    v.goal += shift;
    for (auto& p : v.planned_path) p += shift;
    for (LogSample& x : v.samples) x.pos += shift, x.ref_pos += shift, x.est_pos += shift;
    log.vehicles.push_back(v);
  }
  writeRunFigures(s, recordOfLog(s, log, nullptr), dir);
  const std::string top = slurp(dir / "top.svg");
  for (std::size_t a = 0; a < 32; ++a)
    EXPECT_NE(top.find(svgColour(vehicleColour(a))), std::string::npos) << a;
  // A key entry for the team, not one per vehicle.
  EXPECT_EQ(top.find(">q7<"), std::string::npos);
  const std::string error = slurp(dir / "error.svg");
  EXPECT_NE(error.find("32 vehicles, one colour each"), std::string::npos);
  std::filesystem::remove_all(dir);
}

TEST(Figures, AxesFitTheData) {
  const auto dir = makeFreshDir("fitted_axes");
  const Scenario s = renderTestScenario();  // a 20 x 20 m world
  // 3.1 s of flight: the error figure's time axis ends there (autoscaled, gnuplot ran it to the
  // next tic, 3.5 s).
  RunLog log = straightFlightLog(3.1, 0.25);
  // A 1 m circle around (10, 10) flown instead of the straight line.
  VehicleLog& v = log.vehicles[0];
  for (std::size_t i = 0; i < v.samples.size(); ++i) {
    const double phase = 2.0 * M_PI * static_cast<double>(i) / (v.samples.size() - 1);
    v.samples[i].pos = Eigen::Vector3d(10 + 0.5 * std::cos(phase), 10 + 0.5 * std::sin(phase), 2);
    v.samples[i].ref_pos = v.samples[i].pos;
  }
  v.planned_path = {{10.5, 10, 2}, {10, 10.5, 2}, {9.5, 10, 2}, {10, 9.5, 2}, {10.5, 10, 2}};
  v.goal = {10.5, 10, 2};
  writeRunFigures(s, recordOfLog(s, log, nullptr), dir);
  const std::string error = slurp(dir / "error.svg");
  EXPECT_NE(error.find("> 3</text>"), std::string::npos);
  EXPECT_EQ(error.find("> 3.5</text>"), std::string::npos);
  // The top view spans the circle and its margin (9.3 to 10.7 m), not the world's 0 to 20 m.
  const std::string top = slurp(dir / "top.svg");
  EXPECT_NE(top.find("> 10</text>"), std::string::npos);
  EXPECT_EQ(top.find("> 15</text>"), std::string::npos);
  EXPECT_EQ(top.find("> 20</text>"), std::string::npos);
  std::filesystem::remove_all(dir);
}
