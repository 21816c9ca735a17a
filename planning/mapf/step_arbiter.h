#pragma once
// One synchronous time step of many agents, for the planners that move agents step by step
// (LRA*, potential field): agents propose moves one after another and a move is accepted only if
// it cannot collide with what was accepted before it (no two agents in one cell, no swap, no
// crossing diagonals; entering a cell is allowed only once its occupant has left). Agents that
// propose nothing wait, which never collides, so every executed step is conflict-free.
#include <vector>

#include "core/stop_token.h"
#include "planning/mapf/mapf_grid.h"
#include "planning/mapf/mapf_planner.h"

namespace cosim {

class StepArbiter {
 public:
  StepArbiter(const MapfGrid& grid, const std::vector<int>& positions);

  const std::vector<int>& positions() const { return position_; }
  // Starts a new step: nobody has moved yet.
  void beginStep();
  // Agent `agent` asks to move to `to` (a neighbour of its cell, or its cell to wait). Returns
  // true if accepted; a refused agent may ask again with another target.
  bool tryMove(int agent, int to);
  // Ends the step; returns how many agents changed cell.
  int commitStep();

  // The end of a step-by-step plan: true with result.success once every agent is on its goal;
  // true with result.message once max_steps steps have passed or the deadline has expired.
  bool finished(const std::vector<int>& goals, int max_steps, const StopToken& deadline,
                MapfResult& result) const;
  // The executed paths (on success without the final waits) into result.paths.
  void storePaths(MapfResult& result) const;

 private:
  const MapfGrid* grid_;
  std::vector<int> position_, next_;      // per agent; next_ = -1: undecided
  std::vector<int> occupant_, claimant_;  // per cell: agent there now / agent arriving, or -1
  std::vector<int> move_stamp_;           // per MapfGrid::moveKey: step of its last accepted move
  std::vector<int> claimed_cells_;
  std::vector<std::vector<int>> history_;  // per agent, its cell after every committed step
  int step_ = 0;
};

}  // namespace cosim
