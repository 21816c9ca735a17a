#include "experiments/bench/render_pipeline.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>

#include "render/camera_rig.h"
#include "render/offscreen_context.h"
#include "render/ordered_frame_workers.h"
#include "render/run_outputs.h"
#include "render/run_renderer.h"
#include "run/run_evaluation.h"
#include "sim/world_model.h"

namespace cosim::bench {

namespace {

// The bundled default scenario's world (40 x 30 x 8 m, six obstacles) and airframe, at the
// default 1280x720.
Scenario benchScenario() {
  Scenario s;
  s.file = "bench";
  s.world.bounds_min = {0, 0, 0};
  s.world.bounds_max = {40, 30, 8};
  const auto add = [&](ObstacleType type, Eigen::Vector3d pos, Eigen::Vector3d size, double radius,
                       double height, double yaw) {
    Obstacle o;
    o.type = type;
    o.pos = pos;
    o.size = size;
    o.radius = radius;
    o.height = height;
    o.yaw_deg = yaw;
    s.world.obstacles.push_back(o);
  };
  add(ObstacleType::Box, {10, 8, 3}, {3, 10, 6}, 0, 0, 0);
  add(ObstacleType::Cylinder, {18, 15, 4}, {0, 0, 0}, 1.5, 8, 0);
  add(ObstacleType::Box, {26, 21, 2.5}, {8, 3, 5}, 0, 0, 30);
  add(ObstacleType::Sphere, {30, 8, 4}, {0, 0, 0}, 2, 0, 0);
  add(ObstacleType::Cylinder, {14, 24, 4}, {0, 0, 0}, 1.2, 8, 0);
  add(ObstacleType::Box, {30, 27, 4}, {2, 6, 8}, 0, 0, 0);
  VehicleSpec v;
  v.name = "uav1";
  v.model = "quad_1500g";
  v.model_file = modelsDirectory() / "quad_1500g.xml";
  v.start = {2, 2, 2};
  v.waypoints = {{36, 26, 3}};
  s.vehicles.push_back(v);
  s.motion.planner.name = "theta_star";
  s.motion.trajectory.mode = TrajectoryMode::MinimumSnap;
  return s;
}

// A 30 s flight along a curve through the world, logged at 500 Hz like a real run, with a
// small tracking error so the trail has colours.
RunLog benchLog(const Scenario& s) {
  RunLog log;
  VehicleLog& v = log.vehicles.emplace_back();
  v.name = "uav1";
  v.radius = 0.35;
  v.goal = s.vehicles[0].goal();
  v.planned_path = {{2, 2, 2},         {7.6, 6.2, 7.2},   {12.7, 8.7, 7.2},
                    {20.2, 12.7, 6.2}, {31.6, 21.2, 4.3}, {36, 26, 3}};
  const int n = 15000;
  for (int k = 0; k <= n; ++k) {
    const double f = static_cast<double>(k) / n;
    const double x = f * (v.planned_path.size() - 1);
    const std::size_t i = std::min(static_cast<std::size_t>(x), v.planned_path.size() - 2);
    LogSample sample;
    sample.t = 30.0 * f;
    sample.ref_pos = v.planned_path[i] + (x - i) * (v.planned_path[i + 1] - v.planned_path[i]);
    sample.pos =
        sample.ref_pos + Eigen::Vector3d(0.05 * std::sin(7 * f), 0.04 * std::cos(5 * f), 0.02);
    sample.vel = Eigen::Vector3d(1.2, 0.8, 0.0);
    v.samples.push_back(sample);
  }
  log.sim_time = 30.0;
  return log;
}

double seconds(std::chrono::steady_clock::time_point since) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

// The frames to draw: the scenario and flight, the frame size and count, and the video file the
// pipelines encode to (removed after each).
struct RenderBenchSetup {
  const Scenario& s;
  const RunLog& log;
  const WorldModel& world;
  int width, height, frames;
  std::filesystem::path video;
};

// Bare: the engine's renderer alone on the same model, camera path and frame size; seconds.
double bareRenderSeconds(const RenderBenchSetup& b) {
  const Scenario& s = b.s;
  const RunLog& log = b.log;
  const mjModel* m = b.world.model();
  const int width = b.width, height = b.height, frames = b.frames;
  OffscreenContext ctx(m, width, height);
  mjData* d = mj_makeData(m);
  mj_forward(m, d);
  mjvScene scene;
  mjvCamera cam;
  mjvOption opt;
  mjv_defaultScene(&scene);
  mjv_makeScene(m, &scene, m->ngeom + 100);
  mjv_defaultCamera(&cam);
  mjv_defaultOption(&opt);
  cam.type = mjCAMERA_FREE;
  const CameraRig rig(s, log, static_cast<double>(width) / height);
  std::vector<unsigned char> rgb(static_cast<std::size_t>(width) * height * 3);
  const auto t0 = std::chrono::steady_clock::now();
  for (int k = 0; k < frames; ++k) {
    // The same chase camera poses as the full pipeline below.
    const CameraPose pose = rig.pose(CameraKind::Chase, k / 30.0 + 10.0);
    for (int i = 0; i < 3; ++i) cam.lookat[i] = pose.lookat[i];
    cam.azimuth = pose.azimuth;
    cam.elevation = pose.elevation;
    cam.distance = pose.distance;
    mjv_updateScene(m, d, &opt, nullptr, &cam, mjCAT_ALL, &scene);
    mjr_render(ctx.viewport(), &scene, ctx.context());
    mjr_readPixels(rgb.data(), nullptr, ctx.viewport(), ctx.context());
  }
  const double elapsed = seconds(t0);
  mjv_freeScene(&scene);
  mj_deleteData(d);
  return elapsed;
}

// Full: the video path of `cosim run` (chase camera, all overlays, encoding) over the first
// `frames` frames of the flight at 30 fps; seconds.
double fullPipelineSeconds(const RenderBenchSetup& b) {
  const int width = b.width, height = b.height, frames = b.frames;
  const std::filesystem::path& video = b.video;
  const Scenario& s = b.s;
  const RunRecord record = recordOfLog(s, b.log, b.world);
  RunRenderer renderer(s, record, width, height);
  std::vector<std::uint8_t> rgb;
  const auto t0 = std::chrono::steady_clock::now();
  VideoEncoder encoder(video, width, height, 30);
  for (int k = 0; k < frames; ++k) {
    renderer.render(k / 30.0 + 10.0, CameraKind::Chase, rgb);
    encoder.addFrame(rgb);
  }
  encoder.finish();
  const double elapsed = seconds(t0);
  std::filesystem::remove(video);
  return elapsed;
}

// Parallel: the same frames rendered on `workers` threads, handed to the encoder in order, as
// `cosim run` renders its videos; seconds.
double parallelPipelineSeconds(const RenderBenchSetup& b, int workers) {
  const int width = b.width, height = b.height, frames = b.frames;
  const std::filesystem::path& video = b.video;
  const Scenario& s = b.s;
  const RunRecord record = recordOfLog(s, b.log, b.world);
  const FrameSequence sequence{CameraKind::Chase, frames, 1.0 / 30.0, width, height, 10.0};
  const auto t0 = std::chrono::steady_clock::now();
  VideoEncoder encoder(video, width, height, 30);
  renderFramesInOrder(s, record, sequence, workers,
                      [&](std::vector<std::uint8_t>& rgb) { encoder.addFrame(rgb); });
  encoder.finish();
  const double elapsed = seconds(t0);
  std::filesystem::remove(video);
  return elapsed;
}

}  // namespace

Section benchRenderPipeline(bool quick) {
  const int width = quick ? 320 : 1280, height = quick ? 180 : 720;
  const int frames = quick ? 6 : 60;
  const int rounds = quick ? 1 : 3;
  Scenario s = benchScenario();
  s.render.width = width;
  s.render.height = height;
  const RunLog log = benchLog(s);
  const WorldModel world = WorldModel::build(s);
  const std::filesystem::path video = std::filesystem::temp_directory_path() /
                                      ("cosim_bench_render_" + std::to_string(getpid()) + ".mp4");
  const RenderBenchSetup setup{s, log, world, width, height, frames, video};

  double best_bare = 1e300, best_full = 1e300, best_parallel = 1e300;
  const int workers = defaultRenderWorkers();
  for (int round = 0; round < rounds; ++round) {
    best_bare = std::min(best_bare, bareRenderSeconds(setup));
    best_full = std::min(best_full, fullPipelineSeconds(setup));
    best_parallel = std::min(best_parallel, parallelPipelineSeconds(setup, workers));
  }
  Section out;
  out.name = "render_pipeline";
  const double bare_fps = frames / best_bare, full_fps = frames / best_full,
               parallel_fps = frames / best_parallel;
  out.figures = {{"bare_mjr_render_readpixels_fps", bare_fps, "1/s"},
                 {"full_pipeline_fps", full_fps, "1/s"},
                 {"ratio_full_to_bare", full_fps / bare_fps, "x"},
                 {"parallel_pipeline_fps", parallel_fps, "1/s"},
                 {"parallel_workers", static_cast<double>(workers), ""},
                 {"ratio_parallel_to_bare", parallel_fps / bare_fps, "x"}};
  out.note = std::to_string(width) + "x" + std::to_string(height) + ", " + std::to_string(frames) +
             " frames, best of " + std::to_string(rounds) +
             " rounds, wall clock; target ratio_full_to_bare >= 0.70: " +
             (full_fps / bare_fps >= 0.7 ? "met" : "NOT met") + "; target ratio_parallel_to_bare " +
             ">= 1.5 on 2 cores (" + std::to_string(workers) +
             " workers): " + (parallel_fps / bare_fps >= 1.5 ? "met" : "NOT met") +
             "; the chase views draw no shadows, the bare render the engine's default (with)";
  return out;
}

}  // namespace cosim::bench
