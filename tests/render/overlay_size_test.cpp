// The 2D boxes (state, legend, colour scale) cover about the same share of a 640x360 frame as
// of a 1280x720 one, although MuJoCo's text is as many pixels high in both.
#include <gtest/gtest.h>

#include "render/run_renderer.h"
#include "render_test_scene.h"
#include "run/run_evaluation.h"
#include "sim/world_model.h"

using namespace cosim;
using namespace cosim::test;

namespace {

// Each box's area as a fraction of the frame's.
std::vector<double> boxShares(int width, int height) {
  const Scenario s = renderTestScenario(width, height);
  const WorldModel world = WorldModel::build(s);
  const RunLog log = straightFlightLog(2.0);
  const RunRecord renderer_record = recordOfLog(s, log, world);
  RunRenderer renderer(s, renderer_record, width, height);
  std::vector<std::uint8_t> rgb;
  renderer.render(1.0, "chase", rgb);
  std::vector<double> shares;
  for (const mjrRect& r : renderer.lastOverlayBoxes())
    shares.push_back(static_cast<double>(r.width) * r.height / (width * height));
  return shares;
}

}  // namespace

TEST(OverlaySize, LegendAndColourBarScaleWithTheFrame) {
  const std::vector<double> large = boxShares(1280, 720), small = boxShares(640, 360);
  ASSERT_EQ(large.size(), 3u);  // state box, legend, one colour scale
  ASSERT_EQ(small.size(), 3u);
  // The legend and the colour scale: at most 1.6 times their share of the large frame (the
  // same text on a quarter of the pixels was 3.5 to 4 times).
  EXPECT_LE(small[1], 1.6 * large[1]) << "legend " << small[1] << " vs " << large[1];
  EXPECT_LE(small[2], 1.6 * large[2]) << "colour scale " << small[2] << " vs " << large[2];
  // Everything together leaves most of the small frame to the picture.
  EXPECT_LT(small[0] + small[1] + small[2], 0.22);
}
