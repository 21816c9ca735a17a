#include "sim/flight_simulation.h"

#include "sim/disturbances.h"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace cosim {

VehicleState readVehicleState(const mjModel*, const mjData* d, const VehicleHandles& v) {
  const mjtNum* q = d->qpos + v.qpos_adr;
  const mjtNum* u = d->qvel + v.qvel_adr;
  VehicleState s;
  s.position = {q[0], q[1], q[2]};
  s.attitude = Eigen::Quaterniond(q[3], q[4], q[5], q[6]).normalized();
  s.velocity = {u[0], u[1], u[2]};          // free joint: linear velocity in the world frame
  s.angular_velocity = {u[3], u[4], u[5]};  // free joint: angular velocity in the body frame
  return s;
}

namespace {

// Contact bookkeeping: counts the onsets of contact between a vehicle and anything else,
// except the floor near the vehicle's start or goal (its landing spots). A contact that lasts
// many steps is one collision.
class ContactMonitor {
 public:
  ContactMonitor(const mjModel* m, const WorldModel& world, const Scenario& scenario)
      : m_(m), floor_(world.floorGeom()), owner_(m->ngeom, -1) {
    for (std::size_t v = 0; v < world.vehicles().size(); ++v) {
      for (int g : world.vehicles()[v].geoms) owner_[g] = static_cast<int>(v);
      starts_.push_back(scenario.vehicles[v].start);
      goals_.push_back(scenario.vehicles[v].goal());
    }
  }

  // Cheap when nothing touches: called every physics step.
  void update(const mjData* d, RunLog& log) {
    if (d->ncon == 0 && previous_.empty()) return;
    current_.clear();
    for (int i = 0; i < d->ncon; ++i) {
      const mjContact& c = d->contact[i];
      note(c.geom1, c.geom2, c, d, log);
      note(c.geom2, c.geom1, c, d, log);
    }
    previous_.swap(current_);
  }

 private:
  void note(int mine, int other, const mjContact& c, const mjData* d, RunLog& log) {
    const int v = owner_[mine];
    if (v < 0 || owner_[other] == v) return;
    const Eigen::Vector3d p(c.pos[0], c.pos[1], c.pos[2]);
    if (other == floor_ && (nearXY(p, starts_[v]) || nearXY(p, goals_[v]))) return;
    const long key = static_cast<long>(v) * m_->ngeom + other;
    if (std::find(current_.begin(), current_.end(), key) != current_.end()) return;
    current_.push_back(key);
    if (std::find(previous_.begin(), previous_.end(), key) == previous_.end()) {
      const char* name = mj_id2name(m_, mjOBJ_GEOM, other);
      log.vehicles[v].collisions.push_back(
          {d->time, name ? name : "geom" + std::to_string(other), p});
    }
  }
  static bool nearXY(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
    return (a - b).head<2>().norm() < 1.0;
  }

  const mjModel* m_;
  int floor_;
  std::vector<int> owner_;  // geom -> vehicle index, -1 for the world
  std::vector<Eigen::Vector3d> starts_, goals_;
  std::vector<long> previous_, current_;  // (vehicle, other geom) pairs in contact
};

bool finite(const mjData* d, int nq) {
  for (int i = 0; i < nq; ++i)
    if (!std::isfinite(d->qpos[i])) return false;
  return true;
}

// MuJoCo's answer to a NaN or huge number in the state or the controls is a warning and a reset of
// the data (or zeroed controls): the vehicle would jump back to its start and the log go on as if
// nothing happened.
bool badNumberWarning(const mjData* d) {
  for (int w : {mjWARN_BADQPOS, mjWARN_BADQVEL, mjWARN_BADQACC, mjWARN_BADCTRL})
    if (d->warning[w].number > 0) return true;
  return false;
}

}  // namespace

RunLog simulateFlight(const WorldModel& world, const Scenario& scenario,
                      std::vector<VehiclePilot>& pilots, const FlightOptions& options) {
  const mjModel* m = world.model();
  mjData* d = mj_makeData(m);
  mj_resetData(m, d);
  // Vehicles start hovering: rotors already spinning at hover thrust (the motor lag would
  // otherwise drop every vehicle for its first tens of milliseconds).
  for (const VehicleHandles& v : world.vehicles()) {
    const double hover = v.params.mass * v.params.gravity / 4.0;
    for (int i = 0; i < 4; ++i) {
      d->ctrl[v.actuators[i]] = hover;
      actuatorActivation(m, d, v.actuators[i]) = hover;
    }
  }
  mj_forward(m, d);

  const SimSettings& cfg = options.settings;
  const int steps_per_control =
      std::max(1, static_cast<int>(std::lround(1.0 / (cfg.timestep * cfg.control_rate))));
  const double control_dt = steps_per_control * m->opt.timestep;
  const long max_steps = static_cast<long>(std::ceil(cfg.max_time / m->opt.timestep));
  const auto& vehicles = world.vehicles();

  RunLog log;
  for (std::size_t v = 0; v < vehicles.size(); ++v) {
    VehicleLog vl;
    vl.name = vehicles[v].name;
    vl.radius = vehicles[v].params.radius;
    vl.max_thrust = vehicles[v].params.max_thrust;
    vl.goal = pilots[v].goal;
    vl.planned_path = pilots[v].planned_path;
    vl.samples.reserve(static_cast<std::size_t>(cfg.max_time / control_dt) + 2);
    log.vehicles.push_back(std::move(vl));
    pilots[v].controller->reset();
  }
  ContactMonitor contacts(m, world, scenario);
  Disturbances disturbances(scenario.disturbances, world, scenario.world.bounds_min.z(),
                            scenario.sim.seed);
  const bool disturbed = scenario.disturbances.any();
  const Eigen::Vector3d lo = scenario.world.bounds_min, hi = scenario.world.bounds_max;
  const double far = 10.0 * (hi - lo).norm();

  // Since when each vehicle's mixer has been saturated without a break (negative: it is not).
  std::vector<double> saturated_since(vehicles.size(), -1.0);

  const auto wall_start = std::chrono::steady_clock::now();
  long step = 0;
  log.end_reason = "max_time";
  for (; step < max_steps; ++step) {
    if (step % steps_per_control == 0) {
      if (options.interrupt && options.interrupt->load()) {
        log.end_reason = "interrupted";
        break;
      }
      bool all_done = true;
      for (std::size_t v = 0; v < vehicles.size(); ++v) {
        const VehicleState s = readVehicleState(m, d, vehicles[v]);
        const FlatReference ref = pilots[v].reference->reference(d->time, s);
        const ControlOutput out = pilots[v].controller->update(s, ref, control_dt);
        for (int i = 0; i < 4; ++i) d->ctrl[vehicles[v].actuators[i]] = out.rotor_thrusts[i];

        VehicleLog& vl = log.vehicles[v];
        LogSample& x = vl.samples.emplace_back();
        x.t = d->time;
        x.ref_pos = ref.position;
        x.ref_vel = ref.velocity;
        x.pos = s.position;
        x.vel = s.velocity;
        x.att = s.attitude;
        x.omega = s.angular_velocity;
        x.rotor_cmd = out.rotor_thrusts;
        for (int i = 0; i < 4; ++i)
          x.rotor_thrust[i] = actuatorActivation(m, d, vehicles[v].actuators[i]);
        x.saturated = out.saturated;
        if (!out.saturated) {
          saturated_since[v] = -1.0;
        } else if (saturated_since[v] < 0.0) {
          saturated_since[v] = d->time;
        } else if (d->time - saturated_since[v] > options.max_saturated_time) {
          log.end_reason = "saturated";
        }

        // Arrival: on the final set-point and within the goal tolerance.
        if (!vl.reached_goal && pilots[v].reference->atFinalSetpoint() &&
            (s.position - pilots[v].goal).norm() < cfg.goal_tolerance) {
          vl.reached_goal = true;
          vl.arrival_time = d->time;
        }
        all_done = all_done && vl.reached_goal &&
                   d->time >= vl.arrival_time + options.hold_after_arrival;
        if (!s.position.allFinite() || (s.position - 0.5 * (lo + hi)).norm() > far) {
          log.end_reason = "diverged";
        }
      }
      if (log.end_reason == "diverged" || log.end_reason == "saturated") break;
      if (all_done) {
        log.end_reason = "goal";
        break;
      }
    }
    if (disturbed) disturbances.apply(m, d, m->opt.timestep);
    mj_step(m, d);
    contacts.update(d, log);
    if (!finite(d, m->nq)) {
      log.end_reason = "diverged";
      ++step;
      break;
    }
    if (badNumberWarning(d)) {
      log.end_reason = "unstable";
      ++step;
      break;
    }
  }
  log.wall_time = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  log.sim_time = d->time;
  log.physics_steps = step;
  for (int i = 0; i < mjNWARNING; ++i) log.mujoco_warnings += d->warning[i].number;
  mj_deleteData(d);
  return log;
}

}  // namespace cosim
