#include "experiments/bench/team_scale.h"

#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <filesystem>

#include "control/geometric_controller.h"
#include "experiments/bench/loop_profile_table.h"
#include "run/run_pipeline.h"
#include "sim/aerodynamics.h"
#include "sim/world_model.h"

namespace cosim::bench {

namespace {

// n/2 omni robots driving 4 m along their lanes at their cruise speed, n/2 cf2 hovering 2 m
// above and flying 4 m across them: no planner (the given waypoints), lanes 0.8 m apart.
Scenario teamScenario(int n, double seconds) {
  Scenario s;
  s.file = "team_scale";
  const int robots = n / 2, quads = n - robots;
  const int side =
      static_cast<int>(std::ceil(std::sqrt(static_cast<double>(std::max(robots, quads)))));
  const double pitch = 0.8, room = side * pitch + 6.0;
  s.world.bounds_min = {0, 0, 0};
  s.world.bounds_max = {room, room, 4};
  for (int i = 0; i < robots; ++i) {
    VehicleSpec v;
    v.name = "r" + std::to_string(i);
    v.model = "omni_base";
    v.model_file = modelsDirectory() / "omni_base.urdf";
    v.kind = VehicleKind::GroundRobot;
    v.start = {1.0 + pitch * (i % side), 1.0 + pitch * (i / side), 0.0};
    v.waypoints = {v.start + Eigen::Vector3d(4.0, 0.0, 0.0)};
    s.vehicles.push_back(v);
  }
  for (int i = 0; i < quads; ++i) {
    VehicleSpec v;
    v.name = "q" + std::to_string(i);
    v.model = "cf2";
    v.model_file = modelsDirectory() / "cf2.xml";
    v.start = {1.0 + pitch * (i % side), 1.0 + pitch * (i / side), 2.0};
    v.waypoints = {v.start + Eigen::Vector3d(0.0, 4.0, 0.0)};
    s.vehicles.push_back(v);
  }
  s.sim.timestep = 0.002;
  s.sim.control_rate = 250;
  s.sim.max_time = seconds;
  s.aerial.controller.name = GeometricController::kName;
  s.aerial.controller.gains = ParamSet("team_scale");
  s.aerial.planner.params = ParamSet("team_scale");
  s.aerial.trajectory.params = ParamSet("team_scale");
  s.motion.planner.params = ParamSet("team_scale");
  s.motion.trajectory.params = ParamSet("team_scale");
  s.motion.controller.gains = ParamSet("team_scale");
  return s;
}

// The same world with the MuJoCo actuators cosim composed before: four thrust site actuators per
// quadrotor (gear 0 0 1 0 0 +-k_m/k_f) and one velocity servo per robot drive joint.
std::string withActuators(const WorldModel& world) {
  std::string acts = "<actuator>";
  const mjModel* m = world.model();
  for (const VehicleHandles& v : world.vehicles()) {
    if (v.kind == VehicleKind::GroundRobot) {
      for (int i = 0; i < v.drive.servo_count; ++i) {
        const GroundDrive::Servo& s = v.drive.servos[i];
        const char* joint = mj_id2name(m, mjOBJ_JOINT, m->dof_jntid[s.dof]);
        acts += "<velocity joint=\"" + std::string(joint) + "\" kv=\"" + std::to_string(s.kv) +
                "\" ctrlrange=\"-" + std::to_string(s.max_speed) + " " +
                std::to_string(s.max_speed) + "\" forcerange=\"-" + std::to_string(s.max_force) +
                " " + std::to_string(s.max_force) + "\"/>";
      }
      continue;
    }
    for (int i = 0; i < 4; ++i)
      acts += "<general site=\"" + v.name + "/rotor" + std::to_string(i) + "\" gear=\"0 0 1 0 0 " +
              std::to_string(v.params.spin[i] * v.params.torque_per_thrust) + "\"/>";
  }
  std::string xml = world.xml();
  xml.insert(xml.rfind("</mujoco>"), acts + "</actuator>");
  return xml;
}

mjModel* compile(const std::string& xml) {
  mjVFS vfs;
  mj_defaultVFS(&vfs);
  mj_makeEmptyFileVFS(&vfs, "team.xml", static_cast<int>(xml.size()));
  std::memcpy(vfs.filedata[mj_findFileVFS(&vfs, "team.xml")], xml.data(), xml.size());
  char error[1000] = "";
  mjModel* m = mj_loadXML("team.xml", &vfs, error, sizeof error);
  mj_deleteVFS(&vfs);
  if (!m) throw std::runtime_error(std::string("team_scale: ") + error);
  return m;
}

// Steps per second of bare mj_step on `m` with the quadrotors held in hover: by their free-joint
// force (no actuators), or by their thrust actuators' controls; `cpu_per_step`: the thread's CPU
// seconds per step, if given.
double bareRate(const mjModel* m, const WorldModel& world, long steps, bool actuated,
                double* cpu_per_step = nullptr) {
  mjData* d = mj_makeData(m);
  int a = 0;
  for (const VehicleHandles& v : world.vehicles()) {
    if (v.kind == VehicleKind::GroundRobot) {
      a += v.drive.servo_count;
      continue;
    }
    const double hover = v.params.mass * v.params.gravity / 4.0;
    if (actuated)
      for (int i = 0; i < 4; ++i) d->ctrl[a++] = hover;
    else
      setFreeJointWrench(d, v, Eigen::Vector3d(0, 0, 4 * hover), Eigen::Vector3d::Zero());
  }
  const auto t0 = std::chrono::steady_clock::now();
  const double cpu0 = LoopProfile::threadCpu();
  for (long k = 0; k < steps; ++k) mj_step(m, d);
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (cpu_per_step) *cpu_per_step = (LoopProfile::threadCpu() - cpu0) / steps;
  mj_deleteData(d);
  return steps / s;
}

double peakMemoryMb() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_maxrss / 1024.0;  // kB on Linux
}

// The full loop on `threads` threads (sim/simulation_loop.h), profiled: its speed in x real time.
double loopRate(Scenario s, int n, int threads, LoopProfile& profile) {
  RunRequest request;
  request.out_dir = std::filesystem::temp_directory_path() /
                    ("cosim-team-scale-" + std::to_string(::getpid()) + "-" + std::to_string(n));
  std::filesystem::create_directories(request.out_dir);
  request.video = false;
  request.images = false;
  request.loop_threads = threads;
  request.profile = &profile;
  const RunRecord run = executeRun(s, request);
  std::filesystem::remove_all(request.out_dir);
  return run.metrics.sim_speed_x;
}

}  // namespace

Section benchTeamScale(bool quick) {
  Section out;
  out.name = "team_scale";
  const std::vector<int> sizes =
      quick ? std::vector<int>{10, 100} : std::vector<int>{10, 100, 1000};
  const double seconds = quick ? 0.5 : 2.0;
  // Both sides run with MuJoCo's timers on (a clock read per phase), for the breakdown.
  const MujocoTimers timers;
  std::vector<ProfiledTeam> profiled;
  bool met = true, cpu_met = true;
  for (int n : sizes) {
    Scenario s = teamScenario(n, seconds);
    const WorldModel world = WorldModel::build(s);
    ProfiledTeam team;
    team.agents = n;
    // The loop as a run uses it (one thread), and with its second thread from 100 agents on.
    const double one_rtf = loopRate(s, n, 1, team.one_thread);
    const double two_rtf = n >= 100 ? loopRate(s, n, 2, team.two_threads) : one_rtf;
    const long steps = static_cast<long>(seconds / s.sim.timestep);
    double bare_cpu = 0.0;  // s per step
    const double bare_rtf =
        bareRate(world.model(), world, steps, false, &bare_cpu) * s.sim.timestep;
    // The actuated model is ~100 times slower at 1000 agents: a tenth of the steps there.
    mjModel* actuated = compile(withActuators(world));
    const double actuated_rtf =
        bareRate(actuated, world, n >= 1000 ? steps / 10 : steps, true) * s.sim.timestep;
    mj_deleteModel(actuated);
    const std::string tag = std::to_string(n);
    out.figures.push_back({"loop_rtf_" + tag, one_rtf, "x real time"});
    out.figures.push_back({"loop_two_threads_rtf_" + tag, two_rtf, "x real time"});
    out.figures.push_back({"bare_mj_step_rtf_" + tag, bare_rtf, "x real time"});
    out.figures.push_back({"ratio_loop_to_bare_" + tag, one_rtf / bare_rtf, "x"});
    out.figures.push_back({"ratio_two_threads_to_bare_" + tag, two_rtf / bare_rtf, "x"});
    // The same in CPU time of the loop's thread (robust when other processes share the cores):
    // on one thread, the whole loop; with the second thread, what stays on the loop's thread.
    const auto cpuRatio = [bare_cpu](const LoopProfile& p) {
      return p.physics_steps > 0 && p.cpu > 0 ? bare_cpu * p.physics_steps / p.cpu : 0.0;
    };
    out.figures.push_back({"cpu_ratio_loop_to_bare_" + tag, cpuRatio(team.one_thread), "x"});
    if (n >= 100)
      out.figures.push_back(
          {"cpu_ratio_two_threads_loop_thread_to_bare_" + tag, cpuRatio(team.two_threads), "x"});
    out.figures.push_back({"actuated_model_bare_rtf_" + tag, actuated_rtf, "x real time"});
    out.figures.push_back({"ratio_loop_to_actuated_" + tag, one_rtf / actuated_rtf, "x"});
    out.figures.push_back({"peak_memory_after_" + tag, peakMemoryMb(), "MB"});
    if (n >= 100) {
      met = met && std::max(one_rtf, two_rtf) / bare_rtf >= 0.95;
      cpu_met = cpu_met && std::max(cpuRatio(team.one_thread), cpuRatio(team.two_threads)) >= 0.95;
      addLoopProfileFigures(team, out.figures);
      profiled.push_back(team);
    }
  }
  out.table = loopProfileTable(profiled);
  out.note =
      "half omni robots, half cf2, 2 ms step, control 250 Hz; the full loop (on one thread, and "
      "with controllers and forces on a second thread during mj_step1) against bare mj_step on "
      "the same model, target >= 0.95 at 100 and 1000 agents: in wall time " +
      std::string(met ? "met" : "NOT met") + ", in the loop thread's CPU time " +
      std::string(cpu_met ? "met" : "NOT met") +
      " (wall time needs a free second core); past real time at 1000 agents needs the engine "
      "itself faster (docs/performance.md)";
  return out;
}

}  // namespace cosim::bench
