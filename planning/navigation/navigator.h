#pragma once
// The interface of robots that navigate an unknown map among moving obstacles (seed 000's RNA and
// WF-RNA; D* Lite as the incremental baseline). A navigator is asked one decision at a time:
// "the robot is at this cell at time t; where next?" It senses the world through its field of
// view itself. runNavigation() drives it on a NavigationWorld; a physics simulation can drive
// it the same way with the robot's measured cell.
#include <cstdint>
#include <string>
#include <vector>

#include "planning/navigation/navigation_world.h"
#include "planning/planner_status.h"

namespace cosim {

struct NavigationDecision {
  Cell next;                  // a neighbour of the robot's cell, or that cell itself to wait
  bool give_up = false;       // no way found within the navigator's limits (`note` says why)
  int replans = 0;            // plans made for this decision (collision re-planning included)
  double plan_ms = 0.0;       // time spent sensing and planning for this decision
  std::vector<Cell> planned;  // the plan followed, robot's cell first (empty when none)
  std::string note;           // e.g. "wait: predicted collision", "evade"
};

class Navigator {
 public:
  virtual ~Navigator() = default;
  virtual std::string name() const = 0;
  // Forgets what the robot knew; a run from start to goal in world follows. world must outlive
  // the run.
  virtual void reset(const NavigationWorld& world, const Cell& start, const Cell& goal,
                     std::uint64_t seed) = 0;
  virtual NavigationDecision decide(const Cell& at, double t) = 0;
};

struct NavigationLimits {
  int max_decisions = 0;       // 0: 20 x the number of grid cells
  double time_limit_s = 30.0;  // wall clock for the whole run
  const StopToken* stop = nullptr;  // the caller's token: the run also ends when it expires
  bool record_decisions = false;
};

struct NavigationRun {
  bool reached = false;
  std::vector<Cell> cells;    // executed path: start, then every cell moved to (waits omitted)
  std::vector<double> times;  // arrival time at each of `cells`
  double length = 0.0;        // Euclidean, in cells
  double travel_time = 0.0;   // including waits
  int steps = 0, waits = 0, replans = 0;
  int collisions = 0;  // moves or waits during which the robot overlapped an obstacle
  double mean_plan_ms = 0.0, max_plan_ms = 0.0;  // per decision
  std::string message;                           // why the goal was not reached
  PlannerStatus status = PlannerStatus::Unknown;  // ExactSolution when reached
  std::vector<NavigationDecision> decisions;     // when limits.record_decisions
};

// Runs navigator from start to goal. A decision that is not a legal move on the true map (a
// static obstacle, a jump) ends the run with a message; so do give_up and the limits.
NavigationRun runNavigation(Navigator& navigator, const NavigationWorld& world, const Cell& start,
                            const Cell& goal, const NavigationLimits& limits, std::uint64_t seed);

}  // namespace cosim
