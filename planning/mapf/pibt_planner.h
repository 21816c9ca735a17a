#pragma once
// The `pibt` multi-robot planner: PIBT alone (Okumura, Machida, Defago, Tamura, AIJ 2022), one
// configuration per time step (pibt_step.h, with the swap technique of IJCAI 2023 unless
// swap = false), priorities rising by one per step an agent is off its goal. Very fast and
// scalable but incomplete: it can cycle for ever, so it stops after max_steps steps.
#include "planning/mapf/mapf_planner.h"

namespace cosim {

struct PibtPlannerOptions {
  bool swap = true;
  int max_steps = 0;  // 0: the number of free cells (as WHCA*'s default here), at least 1000
};

class PibtPlanner final : public MapfPlanner {
 public:
  explicit PibtPlanner(PibtPlannerOptions options) : options_(options) {}
  std::string name() const override { return "pibt"; }
  MapfResult solve(const MapfQuery& query, const StopToken& stop) override;

 private:
  PibtPlannerOptions options_;
};

}  // namespace cosim
