#pragma once
// The team_scale section's breakdown of a physics step (experiments/bench/team_scale.h): the
// engine's phases from MuJoCo's own timers, our loop's parts from the loop's profile
// (sim/loop_profile.h), per physics step, one column per team size.
#include <string>
#include <vector>

#include "experiments/bench/bench_section.h"
#include "sim/loop_profile.h"

namespace cosim::bench {

struct ProfiledTeam {
  int agents = 0;
  LoopProfile one_thread;   // the loop on one thread, with MuJoCo's timers on
  LoopProfile two_threads;  // the loop with its second thread
};

// Milliseconds per physics step of each part, one row per part.
std::string loopProfileTable(const std::vector<ProfiledTeam>& teams);

// The same parts as figures ("step_<part>_ms_<agents>"), for --json.
void addLoopProfileFigures(const ProfiledTeam& team, std::vector<Figure>& figures);

// Starts MuJoCo's timers (mjcb_time) for the object's life; restores the previous callback.
class MujocoTimers {
 public:
  MujocoTimers();
  ~MujocoTimers();
  MujocoTimers(const MujocoTimers&) = delete;
  MujocoTimers& operator=(const MujocoTimers&) = delete;

 private:
  mjfTime previous_;
};

}  // namespace cosim::bench
