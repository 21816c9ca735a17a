// One visual language: a frame of the video and a headless-Chromium screenshot of viewer.html at
// the same moment show the same things in the same colours (render/overlay_palette.h).
#include <gtest/gtest.h>

#include <cstdlib>

#include "render/colour_difference.h"
#include "render/overlay_palette.h"
#include "render/run_renderer.h"
#include "render/viewer_page.h"
#include "render_test_scene.h"
#include "run/run_evaluation.h"

using namespace cosim;
using namespace cosim::test;

namespace {

constexpr int kWidth = 640, kHeight = 360;

std::string chromium() {
  for (const char* p : {"/usr/bin/chromium", "/usr/bin/chromium-browser", "/usr/bin/google-chrome"})
    if (std::filesystem::exists(p)) return p;
  return "";
}

// viewer.html at `fragment` as RGB bytes (kWidth x kHeight), through headless Chromium with
// software WebGL and ffmpeg decoding its PNG; empty if either failed.
std::vector<std::uint8_t> viewerScreenshot(const std::filesystem::path& page,
                                           const std::string& fragment) {
  const auto dir = page.parent_path();
  const auto png = dir / "viewer.png", rgb = dir / "viewer.rgb";
  const std::string shot =
      chromium() +
      " --headless --no-sandbox --use-angle=swiftshader --enable-unsafe-swiftshader"
      " --disable-dev-shm-usage --no-first-run --disable-background-networking"
      " --disable-component-update --disable-sync --host-resolver-rules=\"MAP * ~NOTFOUND\""
      " --user-data-dir=" +
      (dir / "chromium-profile").string() + " --window-size=" + std::to_string(kWidth) + "," +
      std::to_string(kHeight) +
      " --hide-scrollbars --virtual-time-budget=8000 --screenshot=" + png.string() + " 'file://" +
      page.string() + fragment + "' > /dev/null 2>&1";
  if (std::system(shot.c_str()) != 0 || !std::filesystem::exists(png)) return {};
  const std::string decode = "ffmpeg -v error -y -i " + png.string() +
                             " -f rawvideo -pix_fmt rgb24 " + rgb.string() + " 2> /dev/null";
  if (std::system(decode.c_str()) != 0) return {};
  const std::string b = slurp(rgb);
  return std::vector<std::uint8_t>(b.begin(), b.end());
}

// Where the pixels within `tolerance` CIEDE2000 of `colour` are: how many, and their mean row.
struct Found {
  int count = 0;
  double mean_row = 0.0;
};
Found pixelsOf(const std::vector<std::uint8_t>& rgb, const Eigen::Vector3f& colour,
               double tolerance) {
  const Eigen::Vector3d want = srgbToLab(colour);
  Found f;
  for (int row = 0; row < kHeight; ++row)
    for (int col = 0; col < kWidth; ++col) {
      const std::size_t k = 3 * (static_cast<std::size_t>(row) * kWidth + col);
      const Eigen::Vector3f px(rgb[k] / 255.0f, rgb[k + 1] / 255.0f, rgb[k + 2] / 255.0f);
      if (ciede2000(srgbToLab(px), want) < tolerance) {
        ++f.count;
        f.mean_row += row;
      }
    }
  if (f.count) f.mean_row /= f.count;
  return f;
}

// Two vehicles of the render test scenario: uav1 flying its straight line, uav2 the same line
// 8 m further along y.
void twoVehicles(Scenario& s, RunLog& log) {
  s.vehicles.push_back(s.vehicles[0]);
  s.vehicles[1].name = "uav2";
  s.vehicles[1].start.y() += 8.0;
  for (auto& w : s.vehicles[1].waypoints) w.y() += 8.0;
  log.vehicles.push_back(log.vehicles[0]);
  VehicleLog& v = log.vehicles[1];
  v.name = "uav2";
  const Eigen::Vector3d shift(0, 8, 0);
  v.goal += shift;
  for (auto& p : v.planned_path) p += shift;
  for (LogSample& x : v.samples) {
    x.pos += shift;
    x.ref_pos += shift;
    x.est_pos += shift;
  }
}

// The same run at time t from the top camera, as viewer.html shows it (a headless-Chromium
// screenshot) and as the video's frame.
struct TwoPictures {
  std::vector<std::uint8_t> viewer, video;
};
TwoPictures viewerAndVideoAt(const Scenario& s, const RunLog& log, const std::filesystem::path& dir,
                             int t) {
  const WorldModel world = WorldModel::build(s);
  const RunRecord record = recordOfLog(s, log, world);
  TwoPictures p;
  EXPECT_EQ(writeRunViewer(dir, world, s, log, "visual language", "ok", &record), "");
  p.viewer = viewerScreenshot(dir / "viewer.html", "#t=" + std::to_string(t) + "&camera=top");
  EXPECT_EQ(p.viewer.size(), static_cast<std::size_t>(kWidth) * kHeight * 3)
      << "Chromium did not run";
  RunRenderer renderer(s, record, kWidth, kHeight);
  renderer.render(t, CameraKind::Top, p.video, /*annotate=*/false);
  EXPECT_EQ(p.video.size(), p.viewer.size());
  return p;
}

}  // namespace

TEST(VisualLanguage, TheVideoAndTheViewerDrawEachVehiclesPathInTheSameColour) {
  if (chromium().empty()) GTEST_SKIP() << "Chromium is not installed (Debian package 'chromium')";
  if (!loadThreeJs().missing.empty()) GTEST_SKIP() << loadThreeJs().missing;
  const auto dir = makeFreshDir("visual_language");
  Scenario s = renderTestScenario(kWidth, kHeight);
  RunLog log = straightFlightLog(6.0);
  twoVehicles(s, log);
  const TwoPictures p = viewerAndVideoAt(s, log, dir, 6);
  if (HasFailure()) return;
  const std::vector<std::uint8_t>& viewer = p.viewer;
  const std::vector<std::uint8_t>& video = p.video;
  // Each vehicle's flown path (a team's: in its own colour) is a few hundred pixels of exactly
  // that colour in both pictures, and the two colours mark two paths 8 m apart, not one.
  const Found video1 = pixelsOf(video, vehicleColour(0), 5.0);
  const Found video2 = pixelsOf(video, vehicleColour(1), 5.0);
  const Found viewer1 = pixelsOf(viewer, vehicleColour(0), 5.0);
  const Found viewer2 = pixelsOf(viewer, vehicleColour(1), 5.0);
  EXPECT_GT(video1.count, 100);
  EXPECT_GT(video2.count, 100);
  EXPECT_GT(viewer1.count, 100);
  EXPECT_GT(viewer2.count, 100);
  EXPECT_GT(std::abs(video2.mean_row - video1.mean_row), 40.0);
  EXPECT_GT(std::abs(viewer2.mean_row - viewer1.mean_row), 40.0);
  if (!HasFailure()) std::filesystem::remove_all(dir);  // else kept: the pictures show why
}

TEST(VisualLanguage, TheVideoAndTheViewerDrawOneVehiclesPlanInTheSameOrange) {
  if (chromium().empty()) GTEST_SKIP() << "Chromium is not installed (Debian package 'chromium')";
  if (!loadThreeJs().missing.empty()) GTEST_SKIP() << loadThreeJs().missing;
  const auto dir = makeFreshDir("visual_language_one");
  const Scenario s = renderTestScenario(kWidth, kHeight);
  const RunLog log = straightFlightLog(6.0);
  const TwoPictures p = viewerAndVideoAt(s, log, dir, 3);
  if (HasFailure()) return;
  const std::vector<std::uint8_t>& viewer = p.viewer;
  const std::vector<std::uint8_t>& video = p.video;
  // The planned path's band, wider than the flown line inside it, shows its orange in both.
  EXPECT_GT(pixelsOf(video, kPlannedPathColour, 5.0).count, 60);
  EXPECT_GT(pixelsOf(viewer, kPlannedPathColour, 5.0).count, 60);
  if (!HasFailure()) std::filesystem::remove_all(dir);
}
