// cosim render RUN_DIR: re-render a logged run without simulating it again.
#include <fstream>
#include <iostream>
#include <sstream>

#include "experiments/cli/command.h"
#include "planning/input_error.h"
#include "render/run_renderer.h"
#include "render/video_encoder.h"
#include "sim/run_log_io.h"
#include "sim/world_model.h"

namespace cosim::cli {

namespace {

std::string readText(const std::filesystem::path& p) {
  std::ifstream in(p);
  if (!in) throw InputError(p.string(), "", "cannot open (is this a run folder?)");
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// The original scenario path recorded in run.json (relative paths in the scenario resolve there).
std::string recordedScenarioFile(const std::filesystem::path& dir) {
  const std::string json = readText(dir / "run.json");
  const std::string key = "\"scenario_file\": \"";
  const auto at = json.find(key);
  if (at == std::string::npos) throw InputError((dir / "run.json").string(), "scenario_file", "missing");
  const auto end = json.find('"', at + key.size());
  return json.substr(at + key.size(), end - at - key.size());
}

}  // namespace

void addRenderCommand(CLI::App& app, CommandContext& ctx) {
  auto* cmd = app.add_subcommand(
      "render",
      "Re-render a logged run from its timeseries.csv and path.csv, without simulating again.\n"
      "Writes a video (.mp4) or, if --out ends in .png, the last frame.");
  struct Args {
    std::string dir, camera, out;
  };
  auto a = std::make_shared<Args>();
  cmd->add_option("run_dir", a->dir, "folder written by cosim run")->required();
  cmd->add_option("--camera", a->camera, "chase, overview or top (default: the scenario's)");
  cmd->add_option("--out", a->out, "output file (default: RUN_DIR/video_<camera>.mp4)");
  cmd->callback([a, &ctx] {
    const std::filesystem::path dir = a->dir;
    const std::string yaml = readText(dir / "scenario.yaml");
    Scenario s = parseScenario(yaml, recordedScenarioFile(dir));
    if (!a->camera.empty()) {
      if (a->camera != "chase" && a->camera != "overview" && a->camera != "top")
        throw InputError("command line", "--camera", "must be chase, overview or top");
      s.render.camera = a->camera;
    }
    RunLog log;
    readPathCsv((dir / "path.csv").string(), log);
    readTimeseriesCsv((dir / "timeseries.csv").string(), log);
    const WorldModel world = WorldModel::build(s);
    for (std::size_t v = 0; v < log.vehicles.size() && v < s.vehicles.size(); ++v) {
      log.vehicles[v].goal = s.vehicles[v].goal();
      log.vehicles[v].radius = world.vehicles()[v].params.radius;
    }
    RunRenderer renderer(world, s, log, s.render.width, s.render.height);
    const std::filesystem::path out =
        a->out.empty() ? dir / ("video_" + s.render.camera + ".mp4") : std::filesystem::path(a->out);
    std::vector<std::uint8_t> rgb;
    if (out.extension() == ".png") {
      renderer.render(renderer.endTime(), s.render.camera, rgb);
      writePng(out, rgb, renderer.width(), renderer.height());
    } else {
      VideoEncoder video(out, s.render.width, s.render.height, s.render.fps);
      const int frames = static_cast<int>(renderer.endTime() * s.render.fps) + 1;
      for (int k = 0; k < frames; ++k) {
        renderer.render(k / static_cast<double>(s.render.fps), s.render.camera, rgb);
        video.addFrame(rgb);
      }
      video.finish();
    }
    std::cout << "rendered: " << out.string() << "\n";
    ctx.status = 0;
  });
}

}  // namespace cosim::cli
