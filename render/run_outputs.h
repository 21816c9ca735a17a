#pragma once
// Everything `cosim run` renders from a run's log into its folder: final.png, the videos (one
// per camera of the scenario's render section, optionally also as PNG frames), the figures
// (figures/*.png and .svg), and index.html showing them with the metrics.
#include <atomic>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "core/json_writer.h"
#include "render/run_renderer.h"
#include "render/video_encoder.h"
#include "sim/run_log.h"
#include "sim/scenario.h"
#include "sim/world_model.h"

namespace cosim {

// Frames of one video: 10 hours at 30 frames per second, more than anyone renders on purpose.
constexpr int kMaxVideoFrames = 1000000;

// Frames of a video of a `duration`-second flight: one every speedup/fps simulated seconds,
// from t = 0 through the end (a 20 s flight at speedup 1 is a 20 s video). Throws InputError
// (place "render") for more than kMaxVideoFrames.
int videoFrameCount(double duration, const RenderSettings& settings);

// Frames done of a video's total, told before the first frame (0) and after each one.
using FrameProgress = std::function<void(int done, int total)>;

// Renders the whole flight from one camera into `out` (an .mp4 or a PNG folder). Returns the
// number of frames. progress: told of the frames done (may be empty). interrupt: polled between
// frames; once it is set, ffmpeg is killed, nothing is written (the partial output is deleted)
// and the result is 0 frames. workers: threads rendering frames at once, each with a renderer of
// its own like `renderer` (render/ordered_frame_workers.h); 0: all cores; 1: `renderer` alone,
// on this thread.
int renderRunVideo(RunRenderer& renderer, const RenderSettings& settings, CameraKind camera,
                   const std::filesystem::path& out, VideoFormat format,
                   const FrameProgress& progress, const std::atomic<bool>* interrupt = nullptr,
                   int workers = 0);
// The same with, if `progress`, a progress bar with the time left on stderr
// (render/progress_bar.h).
int renderRunVideo(RunRenderer& renderer, const RenderSettings& settings, CameraKind camera,
                   const std::filesystem::path& out, VideoFormat format, bool progress,
                   const std::atomic<bool>* interrupt = nullptr, int workers = 0);

// The cameras of a run's videos, in order, without repeats: render.camera, then render.cameras.
std::vector<CameraKind> videoCameras(const RenderSettings& settings);
// The file of a camera's video: video.mp4 for the main camera, video_<camera>.mp4 otherwise.
std::string videoFileName(const RenderSettings& settings, CameraKind camera);

struct RunRenderRequest {
  bool images = true;  // final.png and the figures
  bool video = true;   // the videos
  // What the rendering is doing, for a front end to show (each may be empty): a line as each
  // output starts ("rendering final.png"), and the frames done of each video (what: "rendering
  // video.mp4"). Rendering itself prints nothing.
  std::function<void(const std::string& line)> on_message;
  std::function<void(const std::string& what, int done, int total)> on_progress;
  // A warning for someone not following the progress: a video that will take long to render
  // (render/long_render_warning.h). May be empty.
  std::function<void(const std::string& text)> on_warning;
  // Polled between outputs and before every video frame (SIGINT/SIGTERM): once set, rendering
  // stops, the video being written is deleted and the rest is skipped.
  const std::atomic<bool>* interrupt = nullptr;
};

// Files written, relative to the run folder.
struct RenderedRun {
  std::string final_image;
  std::string viewer;  // viewer.html, the 3D replay ("" if it was not written)
  std::vector<std::string> videos;
  std::vector<std::string> figures;  // base names in figures/ (each as .png and .svg)
  bool interrupted = false;          // stopped by the request's interrupt: outputs are missing
};

// The outputs of the record of a run of `scenario`.
RenderedRun renderRunOutputs(const Scenario& scenario, const RunRecord& record,
                             const std::filesystem::path& dir, const RunRenderRequest& request);

// dir/index.html: the record's title and status line (run/record/run_record.h), the rendered
// files, and `metrics` (metrics.json's object, written from the record) as tables.
void writeRunReport(const std::filesystem::path& dir, const Scenario& scenario,
                    const RunRecord& record, const JsonObject& metrics,
                    const RenderedRun& rendered);

}  // namespace cosim
