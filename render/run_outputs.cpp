#include "render/run_outputs.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>
#include <optional>

#include "core/input_error.h"
#include "core/stop_request.h"
#include "core/stop_requested_error.h"
#include "render/figures.h"
#include "render/html_report.h"
#include "render/log_lookup.h"
#include "render/long_render_warning.h"
#include "render/ordered_frame_workers.h"
#include "render/progress_bar.h"

namespace cosim {

namespace {
bool interrupted(const std::atomic<bool>* flag) {
  return flag && flag->load();
}
}  // namespace

int videoFrameCount(double duration, const RenderSettings& settings) {
  // The small tolerance keeps a flight of exactly k frame periods at k + 1 frames despite
  // rounding in the logged times. Counted in double: a duration of 1e9 s must not wrap an int
  // around to a one-frame video.
  const double periods = std::floor(duration / settings.speedup * settings.fps + 1e-6);
  if (!(periods >= 0.0)) return 1;
  if (periods + 1.0 > static_cast<double>(kMaxVideoFrames))
    throw InputError(
        "", "render",
        "the video would have " + std::to_string(static_cast<long long>(periods + 1.0)) +
            " frames (" + std::to_string(duration) + " s at " + std::to_string(settings.fps) +
            " frames per second, " + std::to_string(settings.speedup) + "x speed-up), more than " +
            std::to_string(kMaxVideoFrames) + ": raise render.speedup or lower render.fps");
  return static_cast<int>(periods) + 1;
}

int renderRunVideo(RunRenderer& renderer, const RenderSettings& settings, CameraKind camera,
                   const std::filesystem::path& out, VideoFormat format, bool progress,
                   const std::atomic<bool>* interrupt, int workers) {
  std::optional<ProgressBar> bar;
  std::optional<LongRenderWarning> warning;
  const FrameProgress show = [&](int done, int total) {
    if (!bar) bar.emplace("rendering " + out.filename().string(), total, progress);
    bar->update(done);
    // Said even without progress (--quiet): it is a warning.
    if (!warning)
      warning.emplace(out.filename().string(), total, [&bar](const std::string& text) {
        bar.reset();  // ends the bar's line first
        std::cerr << "cosim: warning: " << text << std::endl;
      });
    warning->update(done);
  };
  return renderRunVideo(renderer, settings, camera, out, format, show, interrupt, workers);
}

int renderRunVideo(RunRenderer& renderer, const RenderSettings& settings, CameraKind camera,
                   const std::filesystem::path& out, VideoFormat format,
                   const FrameProgress& progress, const std::atomic<bool>* interrupt, int workers) {
  const int frames = videoFrameCount(renderer.endTime(), settings);
  VideoEncoder video(out, renderer.width(), renderer.height(), settings.fps, format);
  const auto bar = [&](int done) {
    if (progress) progress(done, frames);
  };
  bar(0);
  const double seconds_per_frame = settings.speedup / settings.fps;
  if (workers == 0) workers = defaultRenderWorkers();
  int done = 0;
  if (workers == 1) {
    std::vector<std::uint8_t> rgb;
    for (; done < frames && !interrupted(interrupt); ++done) {
      renderer.render(done * seconds_per_frame, camera, rgb);
      video.addFrame(rgb);
      bar(done + 1);
    }
  } else {
    const FrameSequence sequence{camera, frames, seconds_per_frame, renderer.width(),
                                 renderer.height()};
    done = renderFramesInOrder(
        renderer.world(), renderer.scenario(), renderer.log(), sequence, workers,
        [&](std::vector<std::uint8_t>& rgb) {
          video.addFrame(rgb);
          bar(video.frames());
        },
        interrupt);
  }
  if (done < frames) return 0;  // interrupted: ~VideoEncoder kills ffmpeg, deletes the file
  video.finish();
  return frames;
}

std::vector<CameraKind> videoCameras(const RenderSettings& settings) {
  std::vector<CameraKind> cams = {settings.camera};
  for (const auto& c : settings.cameras)
    if (std::find(cams.begin(), cams.end(), c) == cams.end()) cams.push_back(c);
  return cams;
}

std::string videoFileName(const RenderSettings& settings, CameraKind camera) {
  return camera == settings.camera ? "video.mp4"
                                   : std::string("video_") + cameraName(camera) + ".mp4";
}

RenderedRun renderRunOutputs(const WorldModel& world, const Scenario& scenario, const RunLog& log,
                             const std::filesystem::path& dir, const RunRenderRequest& request) {
  RenderedRun done;
  const auto say = [&](const std::string& what) {
    if (request.on_message) request.on_message(what);
  };
  // The progress of a video's frames, and the warning if it will take long (LongRenderWarning).
  const auto frames_of = [&request](const std::filesystem::path& file) -> FrameProgress {
    if (!request.on_progress && !request.on_warning) return nullptr;
    std::shared_ptr<LongRenderWarning> warning;
    return [&request, warning, name = file.filename().string()](int done, int total) mutable {
      if (request.on_progress) request.on_progress("rendering " + name, done, total);
      if (!warning) warning = std::make_shared<LongRenderWarning>(name, total, request.on_warning);
      warning->update(done);
    };
  };
  const RenderSettings& rs = scenario.render;
  RunRenderer renderer(world, scenario, log, rs.width, rs.height);
  const auto stop = [&] { return done.interrupted = interrupted(request.interrupt); };
  if (request.images) {
    if (stop()) return done;
    say("rendering final.png");
    std::vector<std::uint8_t> rgb;
    renderer.render(renderer.endTime(), CameraKind::Overview, rgb);
    writePng(dir / "final.png", rgb, renderer.width(), renderer.height());
    done.final_image = "final.png";
    if (stop()) return done;
    say("plotting figures/");
    try {
      done.figures = writeRunFigures(log, scenario, dir / "figures");
    } catch (const StopRequestedError&) {
      done.interrupted = true;  // gnuplot was ended: no figure was published
      return done;
    }
  }
  if (request.video) {
    for (const CameraKind camera : videoCameras(rs)) {
      if (stop()) return done;
      const std::string file = videoFileName(rs, camera);
      say("rendering " + file + " (" + cameraName(camera) + " camera, " +
          std::to_string(videoFrameCount(renderer.endTime(), rs)) + " frames)");
      renderRunVideo(renderer, rs, camera, dir / file, VideoFormat::Mp4, frames_of(file),
                     request.interrupt);
      if (stop()) return done;
      done.videos.push_back(file);
      if (rs.png_frames) {
        const std::string frames = std::string("frames_") + cameraName(camera);
        renderRunVideo(renderer, rs, camera, dir / frames, VideoFormat::PngSequence,
                       frames_of(frames), request.interrupt);
      }
    }
  }
  stop();
  return done;
}

std::string runReportTitle(const Scenario& scenario) {
  const std::string planner =
      scenario.motion.planner.name.empty() ? "given waypoints" : scenario.motion.planner.name;
  return "cosim run: " + std::filesystem::path(scenario.file).stem().string() + " (" + planner +
         ", " + scenario.motion.controller.name + " controller)";
}

void writeRunReport(const std::filesystem::path& dir, const Scenario& scenario,
                    const std::string& metrics_json, const std::string& failure,
                    const RenderedRun& rendered) {
  HtmlReport r;
  r.title = runReportTitle(scenario);
  r.viewer = rendered.viewer;
  r.subtitle = failure.empty() ? "Every vehicle reached its goal without a collision."
                               : "The run failed its task: " + failure;
  r.videos = rendered.videos;
  for (const auto& f : rendered.figures) r.figures.push_back("figures/" + f);
  if (!rendered.final_image.empty()) r.images.push_back(rendered.final_image);
  r.metrics_json = metrics_json;
  writeHtmlReport(dir, r);
}

}  // namespace cosim
