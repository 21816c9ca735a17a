// cosim render RUN_DIR: re-render a logged run without simulating it again.
#include <iostream>

#include "cli/command.h"
#include "cli/interrupt_flag.h"
#include "cli/option_checks.h"
#include "cli/run_folder.h"
#include "core/input_error.h"
#include "core/output_files.h"
#include "core/output_manifest.h"
#include "render/run_outputs.h"

namespace cosim::cli {

namespace {

struct RenderArgs {
  std::string dir, camera, out;
  bool frames = false, quiet = false;
  double at = -1.0, speedup = 0.0;
  int width = 0, height = 0, fps = 0;
};

// The command line's choices over the scenario's render section: camera, frame size, frame rate
// and time-lapse.
void applyRenderOptions(const RenderArgs& a, Scenario& s) {
  if (!a.camera.empty()) {
    CameraKind camera = CameraKind::Chase;
    try {
      camera = cameraKind(a.camera);
    } catch (const std::invalid_argument&) {
      throw InputError("command line", "--camera", std::string("must be ") + cameraNames());
    }
    if (camera == CameraKind::Fixed && !s.render.has_fixed_camera)
      throw InputError("command line", "--camera",
                       "'fixed' needs render.fixed_camera: {pos: [x, y, z], lookat: [x, y, z]} "
                       "in the scenario");
    s.render.camera = camera;
  }
  if (a.width) s.render.width = a.width;
  if (a.height) s.render.height = a.height;
  if (s.render.width % 2 || s.render.height % 2)
    throw InputError("command line", "--width/--height", "must be even (H.264, yuv420p)");
  if (a.fps) s.render.fps = a.fps;
  if (a.speedup > 0) s.render.speedup = a.speedup;
}

void renderRun(const RenderArgs& a, CommandContext& ctx) {
  const std::atomic<bool>& interrupt = installInterruptFlag();
  const std::filesystem::path dir = a.dir;
  Scenario s = readRunScenario(dir);
  applyRenderOptions(a, s);
  // Where the output goes is checked before anything is read or drawn.
  const CameraKind camera = s.render.camera;
  const std::string name = cameraName(camera);
  std::filesystem::path out = a.out;
  if (out.empty()) out = dir / (a.frames ? "frames_" + name : "video_" + name + ".mp4");
  const bool one_frame = out.extension() == ".png" && !a.frames;
  // The encoder writes MP4 (H.264) only: a name promising another format is refused rather than
  // given MP4 bytes under it.
  if (!a.frames && !one_frame && out.extension() != ".mp4")
    throw InputError(out.string(), "--out",
                     "cosim writes a video as MP4 and one frame as PNG: name the file .mp4 or "
                     ".png (or use --frames for a folder of PNG frames)");
  // Replaces only a file or folder of frames cosim can prove it wrote (core/output_manifest.h).
  checkOutputPath(out, a.out.empty() ? "run folder" : "--out", a.frames);
  // Its world is composed for the frame size asked for (its off-screen buffer fits it).
  const RunRecord record = readRunRecord(dir, s);
  if (interrupt.load()) {
    std::cerr << "cosim: interrupted; " << printableText(out.string()) << " was not written\n";
    ctx.status = 1;
    return;
  }
  RunRenderer renderer(s, record, s.render.width, s.render.height);
  if (one_frame) {
    std::vector<std::uint8_t> rgb;
    renderer.render(a.at >= 0 ? a.at : renderer.endTime(), camera, rgb);
    writePng(out, rgb, renderer.width(), renderer.height());
  } else {
    const int frames = renderRunVideo(renderer, s.render, camera, out,
                                      a.frames ? VideoFormat::PngSequence : VideoFormat::Mp4,
                                      !a.quiet, &interrupt);
    if (frames == 0) {  // SIGINT/SIGTERM: ffmpeg was stopped and its partial output deleted
      std::cerr << "cosim: interrupted; " << printableText(out.string()) << " was not written\n";
      ctx.status = 1;
      return;
    }
    std::cout << "frames: " << frames << " at " << s.render.fps << " fps (" << s.render.speedup
              << "x simulated time)\n";
  }
  writeOutputManifestOf(out, "render");  // proves it cosim's to a later render
  std::cout << "rendered: " << printableText(out.string()) << "\n";
  ctx.status = 0;
}

}  // namespace

void addRenderCommand(CLI::App& app, CommandContext& ctx) {
  auto* cmd = app.add_subcommand(
      "render",
      "Re-render a logged run from its scenario.yaml, timeseries.csv, path.csv and\n"
      "moving_obstacles.csv (if the run had moving obstacles), without\n"
      "simulating again. Writes a video (.mp4), a PNG frame sequence (--frames), or, if --out\n"
      "ends in .png, one frame (the last, or the one at --at).");
  auto a = std::make_shared<RenderArgs>();
  cmd->add_option("run_dir", a->dir, "folder written by cosim run")->required();
  cmd->add_option("--camera", a->camera,
                  "chase, orbit, top, overview or fixed (fixed needs render.fixed_camera in the "
                  "scenario; default: the scenario's render.camera)");
  cmd->add_option("--out", a->out,
                  "output file (default: RUN_DIR/video_<camera>.mp4, or RUN_DIR/frames_<camera>/ "
                  "with --frames)");
  cmd->add_flag("--frames", a->frames,
                "write PNG frames (00001.png, ...) into a folder instead of a video");
  cmd->add_option("--at", a->at, "with --out FILE.png: the frame at this simulated time (s)")
      ->check(numberIn(0.0, 1e9));
  cmd->add_option("--video-speed,--speedup", a->speedup,
                  "time-lapse: simulated seconds per video second (default: the scenario's "
                  "render.speed)")
      ->check(numberIn(0.01, 1000.0));
  cmd->add_option("--fps", a->fps, "frames per second (default: the scenario's)")
      ->check(wholeNumberIn(1, 240));
  cmd->add_option("--width", a->width, "frame width in pixels, even (default: the scenario's)")
      ->check(wholeNumberIn(64, 3840));
  cmd->add_option("--height", a->height, "frame height in pixels, even (default: the scenario's)")
      ->check(wholeNumberIn(64, 2160));
  cmd->add_flag("--quiet", a->quiet, "no progress bar");
  cmd->callback([a, &ctx] { renderRun(*a, ctx); });
}

}  // namespace cosim::cli
