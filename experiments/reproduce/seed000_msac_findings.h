#pragma once
// seed000-msac's closing section and maps: the thesis's MSAC findings (Pěňčík 2014, §6.1, claims
// 1-6 of its summary) checked against this run's tables.
#include <string>
#include <vector>

#include "experiments/reproduce/agreement_section.h"
#include "experiments/reproduce/seed000_runs.h"

namespace cosim::reproduce {

struct MsacResults {
  const std::vector<Seed000Column>& tabu;            // Table 6.1: versions 1, 2, 3
  const std::vector<Seed000Column>& post_scene1;     // Table 6.2: with, without processing
  const std::vector<Seed000Column>& post_scene2;     // Table 6.3
  const std::vector<std::vector<Seed000Column>>& m;  // Tables 6.4-6.7: m = 2, 4, 8
  const Seed000Stats& max1_m1_scene2;                // §6.1.4: MAX 1, m 1 on scene 2
};

std::vector<Finding> msacFindings(const MsacResults& r, const Seed000SceneSet& scenes);

// The three scenes with MSAC's shortest path (m 4, MAX 3, with processing; on scene 2 also
// without): writes seed000-msac_map1..3 and returns the report's section.
std::string msacMaps(const Options& options, const Seed000SceneSet& scenes, const MsacResults& r);

}  // namespace cosim::reproduce
