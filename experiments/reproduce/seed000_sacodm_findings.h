#pragma once
// seed000-sacodm's closing section and maps: the thesis's SACO/SACOdm findings (Pěňčík 2014,
// §6.2-6.3, claims 7-13 of its summary) checked against this run's tables.
#include <string>
#include <vector>

#include "experiments/reproduce/agreement_section.h"
#include "experiments/reproduce/seed000_runs.h"

namespace cosim::reproduce {

// Fig. 6.5 on one scene: first walks of SACO (beta 0, gamma 0), raw and processed.
struct Fig65 {
  int walks = 0, runs = 0;  // walks that reached the goal, of runs
  double raw_mean = 0, raw_max = 0, loop_free_mean = 0, smoothed_mean = 0;
};

struct SacodmResults {
  // Tables 6.8-6.16 in order, each with its columns (as in the report).
  const std::vector<std::vector<Seed000Column>>& tables;
  const Seed000Stats* msac;  // [3]: MSAC m 4, MAX 3 on the free scene, scene 1, scene 2
  const Fig65* fig65;        // [2]: the free scene, scene 2
  const Seed000SceneSet& scenes;
  const Fig65 (&fig64)[2][2];  // Fig. 6.4: [first gamma, rolling][gamma 1, gamma 100]
};

std::vector<Finding> sacodmFindings(const SacodmResults& r);

// The free scene, scene 1 and scene 2 with SACOdm's shortest path (the seed's best setting per
// scene) and MSAC's: writes seed000-sacodm_map1..3 and returns the report's section.
std::string sacodmMaps(const Options& options, const SacodmResults& r);

}  // namespace cosim::reproduce
