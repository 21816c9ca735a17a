#pragma once
// RNA, the Robot Navigation Ant algorithm (Zhu, Hu, Cai, Henschen, Applied Soft Computing 11
// (2011) 4667-4676) with the modifications of seed 000 (Pěňčík 2014, §2.4, §4.2), and WF-RNA,
// the same robot with a wave-front (shortest path) local planner instead of MSAC.
// Every step the robot looks at its square field of view (half-width `sight`), picks a local goal
// (the global goal if in view, else the cell of the ring just outside the view nearest to it; the
// ring is assumed free), plans to it, checks the plan against the predicted motion of the moving
// obstacles in view (blocking collision points and re-planning up to max_replans times), and
// takes the first step. Cells the robot moves back out of become temporary obstacles
// (anti-oscillation). When the static map shows no way, the newest temporary obstacle is lifted
// and MSAC retried with 1.5 S_max; then the robot waits, and gives up after max_waits waits in a
// row (seed 000 §4.2 b). Of the temporary obstacles in view, the newest one not lifted before is
// lifted:
// lifting the very newest each time re-opens only the cell just left, which the robot enters,
// leaves, marks and has lifted again, forever (4 of 10 runs at sight 4 in seed000-rna's dead end).
#include <random>
#include <set>

#include "planning/navigation/collision_prediction.h"
#include "planning/navigation/navigator.h"
#include "planning/swarm/msac.h"

namespace cosim {

struct RnaParams {
  int sight = 10;           // half-width of the square field of view, cells (seed: 6-18)
  bool wave_front = false;  // WF-RNA: shortest-path local planner instead of MSAC
  // Anti-oscillation (the seed's "oscillation type"): false = a return to the previous cell marks
  // the cell left; true = a return to any visited cell does. Default true: only it breaks the
  // longer cycles at the edge of the view (the seed's "region boundary oscillation", §2.4), e.g.
  // a robot stepping in and out of sight of a dead end's end.
  bool oscillation_any = true;
  int max_replans = 5;  // collision re-plans per step before waiting
  int max_waits = 20;   // consecutive waits for want of a static path before giving up
  ObstaclePrediction prediction = ObstaclePrediction::ConstantVelocity;
  bool conditional_diagonal = true;
  MsacParams msac;  // m and MAX (ants, iterations) are RNA inputs; S_max follows the view size
};

class RobotNavigationAnt : public Navigator {
 public:
  explicit RobotNavigationAnt(RnaParams params = {}) : p_(params) {}
  std::string name() const override { return p_.wave_front ? "wf_rna" : "rna"; }
  void reset(const NavigationWorld& world, const Cell& start, const Cell& goal,
             std::uint64_t seed) override;
  NavigationDecision decide(const Cell& at, double t) override;

 private:
  struct Window {
    int x0, y0;
    OccupancyGrid grid;
  };
  Window buildWindow(const Cell& at) const;
  // The global goal if in view and reachable there, else the reachable cell of the ring just
  // outside the view nearest to it.
  bool localGoal(const Window& w, const Cell& at, Cell& goal) const;
  // Plans from at to goal on the window; s_max_scale enlarges MSAC's S_max.
  bool plan(const Window& w, const Cell& at, const Cell& goal, double s_max_scale,
            std::vector<Cell>& path, double time_limit_s);
  bool temporarilyBlocked(const Cell& c) const;
  bool wasLifted(const Cell& c) const;
  // The dead-lock handling's lift (§4.2 b): the newest anti-oscillation obstacle in view not
  // lifted before (or, when all in view were, the newest in view); false if none is in view.
  bool liftNewestTemporary(const Cell& at);
  NavigationDecision evade(const Cell& at, const Cell& goal, const CollisionPredictor& predictor,
                           NavigationDecision d) const;

  RnaParams p_;
  const NavigationWorld* world_ = nullptr;
  Cell goal_;
  std::uint64_t seed_ = 1;
  long long decisions_ = 0;
  int waits_in_a_row_ = 0;
  bool has_previous_ = false;
  Cell previous_;
  std::vector<unsigned char> visited_;
  std::vector<Cell> temporary_;  // anti-oscillation obstacles, newest last
  std::vector<Cell> lifted_;     // anti-oscillation obstacles lifted by the dead-lock handling
};

}  // namespace cosim
