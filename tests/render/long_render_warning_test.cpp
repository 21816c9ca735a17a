// A video that will take long to render is announced once, early, with its frames and the
// estimated time; a short one says nothing.
#include "render/long_render_warning.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

using namespace cosim;

namespace {

struct Said {
  std::vector<std::string> lines;
  std::function<void(const std::string&)> sink() {
    return [this](const std::string& s) { lines.push_back(s); };
  }
};

// The probe's settings: 198 817 frames at 0.21 s a frame are 41 752 s, 11 h 35 min. The rate
// is measured from the first frame on (the first pays for setting up).
TEST(LongRenderWarning, AVideoOfHoursIsAnnouncedOnceWithItsFramesAndTime) {
  Said said;
  LongRenderWarning w("video.mp4", 198817, said.sink());
  w.update(1, 0.5);  // the first frame, slow: not part of the rate
  w.update(5, 1.5);  // too early to estimate: nothing yet
  EXPECT_TRUE(said.lines.empty());
  w.update(11, 2.6);  // 10 frames in 2.1 s since the first
  ASSERT_EQ(said.lines.size(), 1u);
  EXPECT_EQ(said.lines[0],
            "video.mp4 has 198817 frames: at the 0.21 s a frame measured so far, rendering it "
            "takes about 11 h 35 min (lower render.fps or raise render.speedup for a shorter "
            "video; Ctrl-C stops it)");
  w.update(100, 21.0);
  EXPECT_EQ(said.lines.size(), 1u) << "said once";
}

TEST(LongRenderWarning, AVideoOfMinutesSaysNothing) {
  Said said;
  LongRenderWarning w("video.mp4", 2000, said.sink());
  w.update(1, 0.1);
  w.update(21, 2.1);  // 0.1 s a frame: 200 s in all, under the 10 minutes
  w.update(2000, 200.0);
  EXPECT_TRUE(said.lines.empty());
  // Just over the limit: 2.1 s + 5989 frames x 0.1 s = 601 s.
  LongRenderWarning over("video_chase.mp4", 6010, said.sink());
  over.update(1, 0.1);
  over.update(21, 2.1);
  ASSERT_EQ(said.lines.size(), 1u);
  EXPECT_NE(said.lines[0].find("about 10 min 01 s"), std::string::npos) << said.lines[0];
}

}  // namespace
