#pragma once
// What one agent's space-time search must respect, whatever produced it: a reservation table of
// higher-priority agents (CA*, HCA*, WHCA*) or the constraints of a CBS node.
#include <climits>

namespace cosim {

class SpaceTimeConstraints {
 public:
  static constexpr int kForever = INT_MAX;
  virtual ~SpaceTimeConstraints() = default;
  // The agent may not be in `cell` at time t.
  virtual bool cellBlocked(int cell, int t) const = 0;
  // The agent may not move from `from` to `to` (from != to) between t and t + 1.
  virtual bool moveBlocked(int from, int to, int t) const = 0;
  // The latest t with cellBlocked(cell, t), -1 if none, kForever if blocked from some time on.
  virtual int lastBlockedTime(int cell) const = 0;
  // No answer changes for t >= staticFrom() (the search may then merge states by cell).
  virtual int staticFrom() const = 0;
};

// Soft constraints for tie-breaking: how many other agents a step would collide with (the
// conflict avoidance table of Standley 2010, used by CBS, Sharon et al. 2015 §4.3).
class SpaceTimeConflictCounter {
 public:
  virtual ~SpaceTimeConflictCounter() = default;
  // Collisions caused by being at `to` at t + 1 after moving (or waiting) from `from` at t.
  virtual int conflicts(int from, int to, int t) const = 0;
  virtual int staticFrom() const = 0;
};

}  // namespace cosim
