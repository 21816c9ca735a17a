#pragma once
// seed000-msac's closing section and maps: the thesis's MSAC findings (Pěňčík 2014, §6.1, claims
// 1-6 of its summary) checked against this run's tables.
#include <string>
#include <vector>

#include "experiments/reproduce/agreement_section.h"
#include "experiments/reproduce/seed000_runs.h"

namespace cosim::reproduce {

// m 4, MAX 3 on scenes 1 and 2 ([k]) with each iteration-end rule ([0] meeting, [1] shorter path).
struct IterationEndResults {
  Seed000Stats stats[2][2];
};

// The wider-range smoothing's reach (path nodes) in the scene-3 table.
constexpr int kWideSmoothing = 10;

// §6.1.4's scene 3 with light ([0]) and wider-range ([1]) smoothing, m 4, MAX 3.
struct Scene3Results {
  Seed000Scene scene;
  double optimum = 0.0;
  Seed000Stats stats[2];
  int straight[2] = {0, 0};  // runs whose path runs straight down the last column
};

struct MsacResults {
  const std::vector<Seed000Column>& tabu;            // Table 6.1: versions 1, 2, 3
  const std::vector<Seed000Column>& post_scene1;     // Table 6.2: with, without processing
  const std::vector<Seed000Column>& post_scene2;     // Table 6.3
  const std::vector<std::vector<Seed000Column>>& m;  // Tables 6.4-6.7: m = 2, 4, 8
  const Seed000Stats& max1_m1_scene2;                // §6.1.4: MAX 1, m 1 on scene 2
  const IterationEndResults& ends;
  const Scene3Results& scene3;
};

std::vector<Finding> msacFindings(const MsacResults& r, const Seed000SceneSet& scenes);

// The three scenes with MSAC's shortest path (m 4, MAX 3, with processing; on scene 2 also
// without): writes seed000-msac_map1..3 and returns the report's section.
std::string msacMaps(const Options& options, const Seed000SceneSet& scenes, const MsacResults& r);

}  // namespace cosim::reproduce
