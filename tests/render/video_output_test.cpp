// Videos from a logged run: frame count and duration follow simulated time (ffprobe), the
// encoding plays in browsers, PNG sequences are complete.
#include <gtest/gtest.h>

#include <cstdio>

#include "render/run_outputs.h"
#include "render_test_scene.h"
#include "run/run_evaluation.h"

using namespace cosim;
using namespace cosim::test;

namespace {

std::string probe(const std::filesystem::path& video, const std::string& entries) {
  const std::filesystem::path out = video.string() + ".probe";
  const std::string cmd = "ffprobe -v error -count_frames -select_streams v:0 -show_entries " +
                          entries + " -of default=noprint_wrappers=1 " + video.string() + " > " +
                          out.string();
  if (std::system(cmd.c_str()) != 0) return "";
  return slurp(out);
}

double field(const std::string& text, const std::string& key) {
  const auto at = text.find(key + "=");
  return at == std::string::npos ? -1.0 : std::strtod(text.c_str() + at + key.size() + 1, nullptr);
}

}  // namespace

TEST(VideoOutput, FrameCountFollowsSimulatedTimeAndSpeedup) {
  RenderSettings r;
  r.fps = 30;
  EXPECT_EQ(videoFrameCount(20.0, r), 601);  // a 20 s flight: 20 s of video plus the t = 0 frame
  r.speedup = 2.0;
  EXPECT_EQ(videoFrameCount(20.0, r), 301);
  r.speedup = 1.0;
  r.fps = 10;
  EXPECT_EQ(videoFrameCount(0.0, r), 1);
}

TEST(VideoOutput, Mp4HasTheExpectedFramesDurationAndBrowserEncoding) {
  const auto dir = makeFreshDir("mp4");
  Scenario s = renderTestScenario(320, 180);
  s.render.fps = 10;
  const RunLog log = straightFlightLog(2.0);
  const WorldModel world = WorldModel::build(s);
  const RunRecord renderer_record = recordOfLog(s, log, world);
  RunRenderer renderer(s, renderer_record, 320, 180);
  const int frames =
      renderRunVideo(renderer, s.render, CameraKind::Chase, dir / "v.mp4", VideoFormat::Mp4, false);
  EXPECT_EQ(frames, 21);
  const std::string info =
      probe(dir / "v.mp4",
            "stream=codec_name,pix_fmt,width,height,nb_read_frames,r_frame_rate:format=duration");
  ASSERT_FALSE(info.empty());
  EXPECT_NE(info.find("codec_name=h264"), std::string::npos) << info;
  EXPECT_NE(info.find("pix_fmt=yuv420p"), std::string::npos) << info;
  EXPECT_EQ(field(info, "width"), 320.0) << info;
  EXPECT_EQ(field(info, "nb_read_frames"), 21.0) << info;
  EXPECT_NEAR(field(info, "duration"), 2.1, 0.051) << info;  // 21 frames of 0.1 s
  // A 2x speed-up halves the video: 11 frames.
  s.render.speedup = 2.0;
  EXPECT_EQ(renderRunVideo(renderer, s.render, CameraKind::Top, dir / "fast.mp4", VideoFormat::Mp4,
                           false),
            11);
  EXPECT_EQ(field(probe(dir / "fast.mp4", "stream=nb_read_frames"), "nb_read_frames"), 11.0);
  std::filesystem::remove_all(dir);
}

TEST(VideoOutput, PngSequenceHasOneNumberedFramePerVideoFrame) {
  const auto dir = makeFreshDir("png_sequence");
  Scenario s = renderTestScenario(320, 180);
  s.render.fps = 5;
  const RunLog log = straightFlightLog(1.0);
  const WorldModel world = WorldModel::build(s);
  const RunRecord renderer_record = recordOfLog(s, log, world);
  RunRenderer renderer(s, renderer_record, 320, 180);
  EXPECT_EQ(renderRunVideo(renderer, s.render, CameraKind::Orbit, dir / "frames",
                           VideoFormat::PngSequence, false),
            6);
  int files = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir / "frames")) {
    ++files;
    EXPECT_EQ(e.path().extension(), ".png");
  }
  EXPECT_EQ(files, 6);
  EXPECT_TRUE(std::filesystem::exists(dir / "frames" / "00001.png"));
  EXPECT_TRUE(std::filesystem::exists(dir / "frames" / "00006.png"));
  // Nothing left over from writing (no temporary folder next to it).
  int entries = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir)) ++entries;
  EXPECT_EQ(entries, 1);
  std::filesystem::remove_all(dir);
}

TEST(VideoOutput, VideoCamerasListTheMainCameraFirstWithoutRepeats) {
  RenderSettings r;
  r.camera = CameraKind::Chase;
  r.cameras = {CameraKind::Top, CameraKind::Chase, CameraKind::Orbit, CameraKind::Top};
  EXPECT_EQ(videoCameras(r),
            (std::vector<CameraKind>{CameraKind::Chase, CameraKind::Top, CameraKind::Orbit}));
  EXPECT_EQ(videoFileName(r, CameraKind::Chase), "video.mp4");
  EXPECT_EQ(videoFileName(r, CameraKind::Top), "video_top.mp4");
}
