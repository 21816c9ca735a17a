// viewer.html opened in headless Chromium (software WebGL): it draws the run, nothing is fetched,
// #t= picks the moment, and the vehicle is where the page says it is.
#include "render/viewer_page.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <nlohmann/json.hpp>
#include <set>

#include "render_test_scene.h"

using namespace cosim;
using namespace cosim::test;

namespace {

std::string chromium() {
  for (const char* p : {"/usr/bin/chromium", "/usr/bin/chromium-browser", "/usr/bin/google-chrome"})
    if (std::filesystem::exists(p)) return p;
  return "";
}

// Headless Chromium on the page with software WebGL and every host name unresolvable, so a
// request to the network could not succeed. `what`: "--screenshot=FILE" or "--dump-dom".
std::string browse(const std::string& browser, const std::filesystem::path& page,
                   const std::string& fragment, const std::string& what,
                   const std::filesystem::path& out) {
  const std::string cmd =
      browser +
      " --headless --no-sandbox --use-angle=swiftshader --enable-unsafe-swiftshader"
      " --disable-dev-shm-usage --no-first-run --disable-background-networking"
      " --disable-component-update --disable-sync --host-resolver-rules=\"MAP * ~NOTFOUND\""
      " --user-data-dir=" +
      (page.parent_path() / "chromium-profile").string() +
      " --window-size=640,360 --hide-scrollbars --virtual-time-budget=8000 " + what + " 'file://" +
      page.string() + fragment + "' > " + out.string() + " 2> /dev/null";
  if (std::system(cmd.c_str()) != 0) return "";
  return slurp(out);
}

// A screenshot as RGB bytes (ffmpeg decodes the PNG); empty if it could not be taken.
std::vector<std::uint8_t> screenshot(const std::string& browser, const std::filesystem::path& page,
                                     const std::string& fragment, const std::string& name) {
  const auto dir = page.parent_path();
  const auto png = dir / (name + ".png"), rgb = dir / (name + ".rgb");
  browse(browser, page, fragment, "--screenshot=" + png.string(), dir / "shot.log");
  const std::string cmd = "ffmpeg -v error -y -i " + png.string() + " -f rawvideo -pix_fmt rgb24 " +
                          rgb.string() + " 2> /dev/null";
  if (!std::filesystem::exists(png) || std::system(cmd.c_str()) != 0) return {};
  const std::string b = slurp(rgb);
  return std::vector<std::uint8_t>(b.begin(), b.end());
}

// Pixels of a and b (640 x 360 RGB) inside the square of half-width r around (x, y) that differ.
int differingNear(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b, int x,
                  int y, int r) {
  int n = 0;
  for (int j = std::max(0, y - r); j < std::min(360, y + r); ++j)
    for (int i = std::max(0, x - r); i < std::min(640, x + r); ++i) {
      const std::size_t k = 3 * (static_cast<std::size_t>(j) * 640 + i);
      if (std::abs(a[k] - b[k]) + std::abs(a[k + 1] - b[k + 1]) + std::abs(a[k + 2] - b[k + 2]) >
          30)
        ++n;
    }
  return n;
}

// The centre of the pixels of the first vehicle's dot (viewer.js draws it in the flown path colour,
// #2159a6, on top of everything) in a 640 x 360 RGB frame; (-1, -1) if there are fewer than 4.
std::pair<int, int> dotCentre(const std::vector<std::uint8_t>& rgb) {
  long sx = 0, sy = 0, n = 0;
  for (int j = 0; j < 360; ++j)
    for (int i = 0; i < 640; ++i) {
      const std::size_t k = 3 * (static_cast<std::size_t>(j) * 640 + i);
      if (std::abs(rgb[k] - 0x21) < 16 && std::abs(rgb[k + 1] - 0x59) < 16 &&
          std::abs(rgb[k + 2] - 0xa6) < 16) {
        sx += i;
        sy += j;
        ++n;
      }
    }
  if (n < 4) return {-1, -1};
  return {static_cast<int>(sx / n), static_cast<int>(sy / n)};
}

}  // namespace

TEST(ViewerPage, DrawsTheRunAtTheAddressedTimesWithoutTheNetwork) {
  const std::string browser = chromium();
  if (browser.empty()) GTEST_SKIP() << "Chromium is not installed (Debian package 'chromium')";
  if (!loadThreeJs().missing.empty()) GTEST_SKIP() << loadThreeJs().missing;
  const auto dir = makeFreshDir("viewer");
  const Scenario s = renderTestScenario();
  const RunLog log = straightFlightLog(6.0);
  const WorldModel world = WorldModel::build(s);
  ASSERT_EQ(writeRunViewer(dir, world, s, log, "viewer test", "ok"), "");
  const auto page = dir / "viewer.html";
  const std::string html = slurp(page);
  EXPECT_EQ(html.find("src=\"http"), std::string::npos);
  EXPECT_EQ(html.find("href=\"http"), std::string::npos);

  const std::string early = browse(browser, page, "#t=0.5", "--dump-dom", dir / "early.html");
  ASSERT_FALSE(early.empty()) << "Chromium did not run";
  EXPECT_NE(early.find("data-viewer=\"ready\""), std::string::npos) << early.substr(0, 400);
  EXPECT_NE(early.find("data-resources=\"0\""), std::string::npos);
  EXPECT_NE(early.find("data-t=\"0.500\""), std::string::npos);

  const auto a = screenshot(browser, page, "#t=0.5", "early");
  const auto b = screenshot(browser, page, "#t=4", "late");
  ASSERT_EQ(a.size(), 640u * 360u * 3u);
  ASSERT_EQ(b.size(), a.size());
  // Not blank: the floor, the obstacle, the paths and the panels give many distinct colours.
  std::set<int> colours;
  for (std::size_t k = 0; k < a.size(); k += 3)
    colours.insert(a[k] << 16 | a[k + 1] << 8 | a[k + 2]);
  EXPECT_GT(colours.size(), 200u);
  // The vehicle's dot moved on screen, and where it was and where it went the frames differ.
  const auto [ax, ay] = dotCentre(a);
  const auto [bx, by] = dotCentre(b);
  ASSERT_GE(ax, 0) << "no vehicle dot at t = 0.5 s";
  ASSERT_GE(bx, 0) << "no vehicle dot at t = 4 s";
  EXPECT_GT(std::hypot(bx - ax, by - ay), 40.0);
  EXPECT_GT(differingNear(a, b, ax, ay, 5), 10);
  EXPECT_GT(differingNear(a, b, bx, by, 5), 10);
  int total = 0;
  for (std::size_t k = 0; k < a.size(); k += 3) total += a[k] != b[k] || a[k + 1] != b[k + 1];
  EXPECT_LT(total, static_cast<int>(a.size() / 3 / 4)) << "the camera stayed: most pixels agree";
  if (!HasFailure()) std::filesystem::remove_all(dir);  // else kept: the screenshots show why
}

TEST(ViewerPage, WithoutThreeJsNothingIsWrittenAndTheReasonIsGiven) {
  const auto dir = makeFreshDir("viewer_missing");
  const Scenario s = renderTestScenario();
  const WorldModel world = WorldModel::build(s);
  ::setenv("COSIM_THREE_DIR", (dir / "no-three").c_str(), 1);
  const std::string why = writeRunViewer(dir, world, s, straightFlightLog(1.0), "t", "s");
  ::unsetenv("COSIM_THREE_DIR");
  EXPECT_NE(why.find("three.min.js is missing (Debian package libjs-three)"), std::string::npos)
      << why;
  EXPECT_FALSE(std::filesystem::exists(dir / "viewer.html"));
  std::filesystem::remove_all(dir);
}

// The run's data sits in <script type="application/json">: a vehicle named <!--<script> put the
// HTML parser in its double-escaped state and the page's scripts never ran. Every '<', '>', '&'
// and line separator of the data is a JSON escape; the data still parses to the same names.
TEST(ViewerPage, TheDataGivesTheHtmlParserNothingToFindAndParsesToTheSameNames) {
  const ThreeJs three{"/*three*/", "/*orbit*/", "", ""};
  const nlohmann::json data = {
      {"names", {"<!--<script>", "q\"x'y]]>", "a&b</script>", "\xe2\x80\xa8|\xe2\x80\xa9"}}};
  const std::string page = viewerPage(data.dump(), three);
  const auto from = page.find("<script id=\"run-data\" type=\"application/json\">");
  ASSERT_NE(from, std::string::npos);
  const auto start = page.find('>', from) + 1;
  const auto end = page.find("</script>", start);
  const std::string text = page.substr(start, end - start);
  for (const char* absent : {"<", ">", "&", "\xe2\x80\xa8", "\xe2\x80\xa9"})
    EXPECT_EQ(text.find(absent), std::string::npos) << absent << " in " << text;
  EXPECT_EQ(nlohmann::json::parse(text), data);
  EXPECT_NE(text.find("\\u003c!--\\u003cscript\\u003e"), std::string::npos) << text;
}
