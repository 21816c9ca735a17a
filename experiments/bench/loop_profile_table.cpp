#include "experiments/bench/loop_profile_table.h"

#include <chrono>
#include <cstdio>

namespace cosim::bench {

namespace {

struct Part {
  const char* name;
  double ms;  // per physics step
};

double perStep(const LoopProfile& p, double seconds) {
  return p.physics_steps > 0 ? 1e3 * seconds / p.physics_steps : 0.0;
}

double timerPerStep(const LoopProfile& p, int timer) {
  return p.physics_steps > 0 ? p.mujoco_ms[timer] / p.physics_steps : 0.0;
}

// MuJoCo's phases (mjtTimer) folded into the parts the table shows; integration is the engine's
// time outside mj_forward's phases (mj_Euler and the bad-state checks).
std::vector<Part> parts(const ProfiledTeam& t) {
  const LoopProfile& p = t.one_thread;
  const double collision = timerPerStep(p, mjTIMER_POS_COLLISION);
  const double constraint = timerPerStep(p, mjTIMER_POS_MAKE) +
                            timerPerStep(p, mjTIMER_POS_PROJECT) +
                            timerPerStep(p, mjTIMER_CONSTRAINT);
  const double position = timerPerStep(p, mjTIMER_POSITION);
  const double dynamics = timerPerStep(p, mjTIMER_VELOCITY) + timerPerStep(p, mjTIMER_ACTUATION) +
                          timerPerStep(p, mjTIMER_ACCELERATION);
  const double engine = perStep(p, p.engine);
  const double logging = perStep(p, p.logging());
  return {
      {"engine_collision", collision},
      {"engine_constraint", constraint},
      {"engine_kinematics_inertia", position - collision - timerPerStep(p, mjTIMER_POS_MAKE) -
                                        timerPerStep(p, mjTIMER_POS_PROJECT)},
      {"engine_velocity_acceleration", dynamics},
      {"engine_integration", engine - position - dynamics - timerPerStep(p, mjTIMER_CONSTRAINT)},
      {"engine", engine},
      {"loop_controllers", perStep(p, p.controllers) - logging},
      {"loop_logging", logging},
      {"loop_rotors_air_servos", perStep(p, p.forces)},
      {"loop_contacts_sensors_health", perStep(p, p.after_step)},
      {"wall_one_thread", perStep(p, p.wall)},
      {"waited_for_second_thread", perStep(t.two_threads, t.two_threads.waited)},
      {"wall_two_threads", perStep(t.two_threads, t.two_threads.wall)},
  };
}

mjtNum nowMs() {
  return std::chrono::duration<double, std::milli>(
             std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

}  // namespace

std::string loopProfileTable(const std::vector<ProfiledTeam>& teams) {
  if (teams.empty()) return "";
  char line[160];
  std::string out = "  ms per physics step              ";
  for (const ProfiledTeam& t : teams) {
    std::snprintf(line, sizeof line, "%10d agents", t.agents);
    out += line;
  }
  out += "\n";
  std::vector<std::vector<Part>> columns;
  for (const ProfiledTeam& t : teams) columns.push_back(parts(t));
  for (std::size_t r = 0; r < columns.front().size(); ++r) {
    std::snprintf(line, sizeof line, "    %-30s", columns.front()[r].name);
    out += line;
    for (const auto& c : columns) {
      std::snprintf(line, sizeof line, "%17.4f", c[r].ms);
      out += line;
    }
    out += "\n";
  }
  return out;
}

void addLoopProfileFigures(const ProfiledTeam& team, std::vector<Figure>& figures) {
  for (const Part& p : parts(team))
    figures.push_back(
        {"step_" + std::string(p.name) + "_ms_" + std::to_string(team.agents), p.ms, "ms"});
}

MujocoTimers::MujocoTimers() : previous_(mjcb_time) {
  mjcb_time = nowMs;
}

MujocoTimers::~MujocoTimers() {
  mjcb_time = previous_;
}

}  // namespace cosim::bench
