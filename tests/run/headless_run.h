#pragma once
// Runs a scenario in-process through `cosim run`'s pipeline, without pictures, in a scratch
// folder, and hands back its metrics.json.
#include <filesystem>
#include <string>

#include "run/run_pipeline.h"
#include "tests/support/test_files.h"

namespace cosim::test {

inline RunRecord runWithoutPictures(Scenario s, const std::string& name, std::string& metrics) {
  RunRequest request;
  request.out_dir = freshDir(name);
  std::filesystem::create_directories(request.out_dir);
  request.video = false;
  request.images = false;
  const RunRecord summary = executeRun(s, request);
  metrics = slurp(request.out_dir / "metrics.json");
  std::filesystem::remove_all(request.out_dir);
  return summary;
}

}  // namespace cosim::test
