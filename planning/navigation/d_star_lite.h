#pragma once
// D* Lite (Koenig & Likhachev, "D* Lite", AAAI 2002; the version with the key modifier k_m, their
// Fig. 3): an incremental search from the goal to the robot on the map the robot knows, with
// unknown cells assumed free. When the field of view reveals cells that differ from what was
// assumed, only the affected vertices are updated and the search repairs its g-values instead of
// starting over. The baseline that seed 000's RNA is compared with (path length, planning time).
// Moving obstacles: the plan is checked with the same CollisionPredictor as RNA's; a step that
// would collide is replaced by waiting (or evading when waiting is unsafe); the static search is
// not changed by them.
#include <queue>

#include "planning/navigation/collision_prediction.h"
#include "planning/navigation/navigator.h"

namespace cosim {

struct DStarLiteParams {
  int sight = 10;
  bool conditional_diagonal = true;
  ObstaclePrediction prediction = ObstaclePrediction::ConstantVelocity;
};

class DStarLite : public Navigator {
 public:
  explicit DStarLite(DStarLiteParams params = {}) : p_(params) {}
  std::string name() const override { return "d_star_lite"; }
  void reset(const NavigationWorld& world, const Cell& start, const Cell& goal,
             std::uint64_t seed) override;
  NavigationDecision decide(const Cell& at, double t) override;
  long long expansions() const { return expansions_; }

 private:
  struct Key {
    double k1, k2;
    bool operator<(const Key& o) const { return k1 < o.k1 || (k1 == o.k1 && k2 < o.k2); }
    bool operator==(const Key& o) const { return k1 == o.k1 && k2 == o.k2; }
  };
  struct Entry {
    Key key;
    int cell;
    bool operator>(const Entry& o) const { return o.key < key; }
  };

  double h(int a, int b) const;     // octile distance
  double cost(int a, int b) const;  // edge cost on the known map (inf if blocked)
  Key calculateKey(int s) const;
  void updateVertex(int u);
  void push(int u, const Key& k);
  bool computeShortestPath(double time_limit_s);
  int neighbourCells(int u, int* out) const;  // the up-to-8 cells around u inside the map
  int bestSuccessor(int u) const;
  std::vector<Cell> extractPlan(int from, int max_steps) const;

  DStarLiteParams p_;
  const NavigationWorld* world_ = nullptr;
  int nx_ = 0, ny_ = 0, start_ = 0, goal_ = 0, last_ = 0;
  double km_ = 0.0;
  std::vector<double> g_, rhs_;
  std::vector<unsigned char> known_blocked_, queued_;
  std::vector<Key> queued_key_;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> open_;
  long long expansions_ = 0;
  bool planned_once_ = false;
};

}  // namespace cosim
