#include "experiments/bench/mapf_planners.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "experiments/reproduce/mapf_trial.h"
#include "planning/mapf/movingai_instance.h"

namespace cosim::bench {

namespace {

struct BenchMap {
  const char* name;
  std::string map, scen;
};

// Best of `repeats` runs (the machine is shared; the minimum is the least disturbed figure).
MapfTrial bestOf(int repeats, const char* planner, const MapfInstance& inst, double limit_s) {
  MapfTrial best;
  for (int i = 0; i < repeats; ++i) {
    const MapfTrial t = runMapfTrial(planner, {}, inst, limit_s, 1);
    if (i == 0 || t.time_ms < best.time_ms) best = t;
  }
  return best;
}

}  // namespace

Section benchMapfPlanners(bool quick) {
  const std::string data = std::string(COSIM_SOURCE_DIR) + "/experiments/maps/";
  const std::vector<BenchMap> maps = {
      {"random32", data + "random-32-32-10.map", data + "random-32-32-10-random-1.scen"},
      {"warehouse", data + "warehouse-10-20-10-2-1.map",
       data + "warehouse-10-20-10-2-1-random-1.scen"},
  };
  const std::vector<int> counts =
      quick ? std::vector<int>{10, 20} : std::vector<int>{10, 20, 50, 100};
  const int repeats = quick ? 1 : 3;
  Section s;
  s.name = "mapf_whca_vs_cbs";
  bool whca_target = true, cbs_target = true;
  for (const auto& m : maps) {
    for (const int n : counts) {
      const MapfInstance inst = readMovingAIMapfInstance(m.map, m.scen, n);
      const std::string tag = std::string(m.name) + "_" + std::to_string(n);
      const MapfTrial w = bestOf(repeats, "whca_star", inst, 10.0);
      s.figures.push_back({"whca_ms_" + tag, w.solved ? w.time_ms : NAN, "ms"});
      if (m.name == std::string("random32") && n == 100 && !(w.solved && w.time_ms < 100.0))
        whca_target = false;
      if (n > 50) continue;  // CBS beyond 50 agents runs into its time limit on these maps
      const MapfTrial c = bestOf(n <= 20 ? repeats : 1, "cbs", inst, quick ? 2.0 : 10.0);
      s.figures.push_back({"cbs_ms_" + tag, c.solved ? c.time_ms : NAN, "ms"});
      if (n == 20) {
        if (!(c.solved && c.time_ms < 1000.0)) cbs_target = false;
        s.figures.push_back(
            {"cbs_over_whca_time_" + tag, c.solved && w.solved ? c.time_ms / w.time_ms : NAN, "x"});
        s.figures.push_back(
            {"whca_over_cbs_soc_" + tag,
             c.solved && w.solved ? static_cast<double>(w.sum_of_costs) / c.sum_of_costs : NAN,
             "x"});
      }
    }
  }
  s.note = std::string("WHCA* vs CBS planning time on the same instances (best of ") +
           std::to_string(repeats) + "); targets: WHCA* 100 agents on random-32-32-10 < 100 ms " +
           (quick         ? "(not run in quick mode)"
            : whca_target ? "(met)"
                          : "(MISSED)") +
           ", CBS 20 agents < 1 s on both maps " + (cbs_target ? "(met)" : "(MISSED)");
  return s;
}

}  // namespace cosim::bench
