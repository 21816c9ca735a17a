#include "sim/ground_simulation.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "sim/ground_vehicle_handles.h"
#include "sim/moving_obstacle_motion.h"
#include "sim/physics_stepper.h"

namespace cosim {

PlanarState readPlanarState(const mjData* d, const VehicleHandles& v) {
  const mjtNum* q = d->qpos + v.qpos_adr;
  const mjtNum* u = d->qvel + v.qvel_adr;
  PlanarState s;
  s.position = {q[0], q[1]};
  s.velocity = {u[0], u[1]};
  if (v.drive.planar_root) {  // slide x, slide y (from the start), hinge yaw
    s.position += v.drive.planar_origin;
    s.yaw = q[2];
    s.yaw_rate = u[2];
  } else {  // free joint: x y z qw qx qy qz; angular velocity in the body frame
    s.yaw = std::atan2(2.0 * (q[3] * q[6] + q[4] * q[5]), 1.0 - 2.0 * (q[5] * q[5] + q[6] * q[6]));
    s.yaw_rate = u[5];
  }
  return s;
}

namespace {

Eigen::Quaterniond attitude(const mjData* d, const VehicleHandles& v) {
  const mjtNum* q = d->qpos + v.qpos_adr;
  if (v.drive.planar_root)
    return Eigen::Quaterniond(Eigen::AngleAxisd(q[2], Eigen::Vector3d::UnitZ()));
  return Eigen::Quaterniond(q[3], q[4], q[5], q[6]).normalized();
}

// The drive servos' set-points for a body-frame command.
void actuate(PhysicsStepper& physics, std::size_t index, const VehicleHandles& v,
             const PlanarState& s, const GroundCommand& c) {
  if (v.drive.kind == GroundDrive::Kind::Holonomic) {
    const double cy = std::cos(s.yaw), sy = std::sin(s.yaw);
    physics.commandDrive(index, 0, cy * c.forward - sy * c.lateral);
    physics.commandDrive(index, 1, sy * c.forward + cy * c.lateral);
    physics.commandDrive(index, 2, c.yaw_rate);
  } else {
    // Wheel speeds of a differential drive: (v -+ w s / 2) / r.
    const double half = 0.5 * v.drive.wheel_separation * c.yaw_rate;
    physics.commandDrive(index, 0, (c.forward - half) / v.drive.wheel_radius);
    physics.commandDrive(index, 1, (c.forward + half) / v.drive.wheel_radius);
  }
}

}  // namespace

RunLog simulateGround(const WorldModel& world, const Scenario& scenario,
                      std::vector<GroundPilot>& pilots, const GroundSimOptions& options) {
  std::vector<VehiclePilot> none;
  return simulateGround(world, scenario, pilots, none, options);
}

RunLog simulateGround(const WorldModel& world, const Scenario& scenario,
                      std::vector<GroundPilot>& robots, std::vector<VehiclePilot>& quadrotors,
                      const GroundSimOptions& options) {
  const mjModel* m = world.model();
  const auto& vehicles = world.vehicles();
  // Which pilot drives vehicle v: robots[pilot[v]] or quadrotors[pilot[v]].
  std::vector<std::size_t> pilot(vehicles.size());
  std::size_t robot_count = 0, quadrotor_count = 0;
  for (std::size_t v = 0; v < vehicles.size(); ++v)
    pilot[v] = vehicles[v].ground ? robot_count++ : quadrotor_count++;
  if (robot_count != robots.size() || quadrotor_count != quadrotors.size())
    throw std::invalid_argument("simulateGround: one pilot per ground robot and per quadrotor");

  mjData* d = mj_makeData(m);
  mj_resetData(m, d);
  for (const auto& v : vehicles)
    if (v.drive.planar_root) setPlanarPose(d, v, v.drive.planar_origin, v.drive.start_yaw);
  const SimSettings& cfg = options.settings;
  PhysicsStepper physics(world, scenario, cfg);
  physics.startHovering(d);
  const double control_dt = physics.controlDt();
  const int controls_per_log =
      std::max(1, static_cast<int>(std::ceil(1.0 / (options.log_rate * control_dt) - 1e-9)));

  // Moving obstacles: mocap bodies placed from their trajectories.
  auto obstacle_xy =
      options.obstacle_position ? options.obstacle_position : [&scenario](std::size_t i, double t) {
        return movingObstaclePosition(scenario.moving_obstacles[i], t);
      };
  std::vector<int> mocap;
  RunLog log;
  for (std::size_t i = 0; i < scenario.moving_obstacles.size(); ++i) {
    const int body = mj_name2id(m, mjOBJ_BODY, movingObstacleName(i).c_str());
    mocap.push_back(body >= 0 ? m->body_mocapid[body] : -1);
    MovingObstacleLog& ol = log.moving_obstacles.emplace_back();
    ol.name = movingObstacleName(i);
    ol.radius = movingObstacleFootprintRadius(scenario.moving_obstacles[i]);
  }
  const auto placeObstacles = [&](double t) {
    for (std::size_t i = 0; i < mocap.size(); ++i) {
      if (mocap[i] < 0) continue;
      const Eigen::Vector2d p = obstacle_xy(i, t);
      d->mocap_pos[3 * mocap[i]] = p.x();
      d->mocap_pos[3 * mocap[i] + 1] = p.y();
    }
  };
  placeObstacles(0.0);
  mj_forward(m, d);

  const AerialStepRules rules(cfg, scenario.world, options.aerial_hold_after_arrival,
                              options.max_saturated_time);
  const AerialSensing sensing{scenario.sensors, scenario.estimator, cfg.seed};
  std::vector<AerialPilotStep> flights;
  for (std::size_t v = 0; v < vehicles.size(); ++v) {
    if (!vehicles[v].ground) {
      AerialPilotStep& f = flights.emplace_back(vehicles[v], quadrotors[pilot[v]], rules, sensing, v);
      log.vehicles.push_back(f.begin(
          d, static_cast<std::size_t>(cfg.max_time / (controls_per_log * control_dt)) + 2));
      continue;
    }
    const GroundPilot& p = robots[pilot[v]];
    VehicleLog& vl = log.vehicles.emplace_back();
    vl.name = vehicles[v].name;
    vl.radius = vehicles[v].params.radius;
    vl.goal = p.goal;
    vl.planned_path = p.planned_path;
    p.controller->reset();
  }
  std::vector<PlanarState> states(robots.size());

  physics.startClock();
  long control_count = 0;
  log.end_reason = "max_time";
  for (long step = 0; step < physics.maxSteps(); ++step) {
    if (step % physics.stepsPerControl() == 0) {
      if (options.interrupt && options.interrupt->load()) {
        log.end_reason = "interrupted";
        break;
      }
      for (std::size_t v = 0; v < vehicles.size(); ++v)
        if (vehicles[v].ground) states[pilot[v]] = readPlanarState(d, vehicles[v]);
      if (options.before_control && !options.before_control(d->time, states)) {
        log.end_reason = "gave_up";
        break;
      }
      const bool record = control_count++ % controls_per_log == 0;
      bool all_done = true, diverged = false, saturated = false;
      for (std::size_t v = 0; v < vehicles.size(); ++v) {
        VehicleLog& vl = log.vehicles[v];
        if (!vehicles[v].ground) {
          const AerialPilotStep::Outcome o =
              flights[pilot[v]].step(d, physics.plant(v), control_dt, vl, record);
          all_done = all_done && o.done;
          diverged = diverged || o.diverged;
          saturated = saturated || o.saturated;
          continue;
        }
        GroundPilot& gp = robots[pilot[v]];
        const PlanarState& s = states[pilot[v]];
        PlanarReference ref = gp.path->sample(d->time);
        ref.yaw = gp.yaw;
        const GroundCommand cmd = gp.controller->update(s, ref, control_dt);
        actuate(physics, v, vehicles[v], s, cmd);

        // Height: the free base's z; a planar base rides at its fixed height (logged as 0).
        const double z = vehicles[v].drive.planar_root ? 0.0 : d->qpos[vehicles[v].qpos_adr + 2];
        const Eigen::Vector3d pos(s.position.x(), s.position.y(), z);
        if (!vl.reached_goal && ref.final &&
            (pos - gp.goal).head<2>().norm() < cfg.goal_tolerance) {
          vl.reached_goal = true;
          vl.arrival_time = d->time;
        }
        all_done =
            all_done && vl.reached_goal && d->time >= vl.arrival_time + options.hold_after_arrival;
        diverged = diverged || !pos.allFinite();
        if (!record) continue;
        LogSample& x = vl.samples.emplace_back();
        x.t = d->time;
        x.ref_pos = {ref.position.x(), ref.position.y(), 0.0};
        x.ref_vel = {ref.velocity.x(), ref.velocity.y(), 0.0};
        x.pos = pos;
        x.vel = {s.velocity.x(), s.velocity.y(), 0.0};
        x.att = attitude(d, vehicles[v]);
        x.omega = {0.0, 0.0, s.yaw_rate};
        x.est_pos = x.pos;  // a robot's controller reads its exact state
        x.est_vel = x.vel;
        x.est_att = x.att;
        // "Rotor" columns of a ground robot: its drive servos' set-points and forces.
        for (int i = 0; i < vehicles[v].drive.servo_count; ++i) {
          x.rotor_cmd[i] = physics.driveCommand(v, i);
          x.rotor_thrust[i] = physics.driveForce(v, i);
        }
        x.saturated = cmd.saturated;
      }
      if (record)
        for (std::size_t i = 0; i < mocap.size(); ++i) {
          const Eigen::Vector2d p = obstacle_xy(i, d->time);
          log.moving_obstacles[i].t.push_back(d->time);
          log.moving_obstacles[i].pos.push_back({p.x(), p.y(), 0.0});
        }
      if (diverged || saturated) {
        log.end_reason = diverged ? "diverged" : "saturated";
        break;
      }
      if (all_done) {
        log.end_reason = "goal";
        break;
      }
    }
    placeObstacles(d->time);
    // (Wind, rotor drag and ground effect act on the quadrotors flying over the robots.)
    if (const char* fault = physics.step(d, log)) {
      log.end_reason = fault;
      break;
    }
  }
  physics.finish(d, log);
  mj_deleteData(d);
  return log;
}

}  // namespace cosim
