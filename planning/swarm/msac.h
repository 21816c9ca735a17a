#pragma once
// MSAC, Multi-Scout Ants Cooperation (Zhu, Hu, Cai, Henschen, Applied Soft Computing 11 (2011)
// 4667-4676), with the modifications of seed 000 (Pěňčík 2014, §4.3): a pheromone-free search by
// two groups of m scout ants, one from the start and one from the goal, moving greedily towards
// the other end over cells no ant has explored yet, randomly over explored ones, and backing out
// of dead ends, which they mark as temporary obstacles. A path is found when an ant has a cell of
// an opposite-group ant's path in its 3x3 neighbourhood; the two paths are joined.
#include <cstdint>

#include "planning/grid/grid_planner.h"

namespace cosim {

// What ends one of MSAC's MAX iterations (besides S_max steps).
enum class MsacIterationEnd {
  // The thesis (seed 000 §4.3): "the process ends either when an ant of one group comes upon the
  // path of an ant of the other group, or when the number of steps exceeds S_max"; the joined
  // path replaces the best so far if shorter.
  Meeting,
  // Step 6 of the algorithm read literally: only a meeting that gives a path shorter than the
  // best so far ends the iteration; after the first iteration, a meeting that gives an equal or
  // longer path lets the scouts walk on, often until S_max.
  ShorterPath,
};

struct MsacParams {
  int ants = 4;                 // m, ants per group ([41]'s typical value)
  int iterations = 3;           // MAX, outer iterations (seed: 3)
  int s_max = 0;                // steps per iteration; 0 = N*N/2 with N the larger grid side (seed)
  bool post_processing = true;  // cycle removal + light smoothing of each found path
  // > 1: also the wider-range smoothing over this many path nodes (AntPathProcessing::
  // smoothWide; the author's proposed extension); 1: the seed's light smoothing only.
  int smoothing_range = 1;
  bool conditional_diagonal = true;  // see AntGridView
  // Tabu table encoding of §4.3.1: 1 explored yes/no (meetings are looked up in every path of
  // the other group), 2 which group explored a cell, 3 group and ant in one uint8 (final).
  int tabu_version = 3;
  bool keep_dead_ends = true;  // §4.3.2 conditional transfer of dead-end marks between iterations
  MsacIterationEnd iteration_end = MsacIterationEnd::Meeting;
};

class Msac : public GridPlanner {
 public:
  explicit Msac(MsacParams params = {}) : p_(params) {}
  std::string name() const override { return "msac"; }
  GridPlanResult solveGrid(const GridQuery& query, const StopToken& stop) override;
  const MsacParams& params() const { return p_; }

 private:
  MsacParams p_;
};

}  // namespace cosim
