#include "sim/simulation_loop.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "sim/ground_vehicle_handles.h"
#include "sim/log_growth.h"
#include "sim/moving_obstacle_motion.h"

namespace cosim {

namespace {

// Which pilot drives each vehicle of the world: its index among the robots or the quadrotors.
std::vector<std::size_t> pilotIndices(const WorldModel& world, std::size_t robots,
                                      std::size_t quadrotors) {
  const auto& vehicles = world.vehicles();
  std::vector<std::size_t> pilot(vehicles.size());
  std::size_t robot_count = 0, quadrotor_count = 0;
  for (std::size_t v = 0; v < vehicles.size(); ++v)
    pilot[v] = vehicles[v].kind == VehicleKind::GroundRobot ? robot_count++ : quadrotor_count++;
  if (robot_count != robots || quadrotor_count != quadrotors)
    throw std::invalid_argument("SimulationLoop: one pilot per ground robot and per quadrotor");
  return pilot;
}

double seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

// Adds the seconds since `start` to `total` (when profiling) and returns now.
double lap(double start, double* total) {
  const double now = seconds();
  *total += now - start;
  return now;
}

}  // namespace

SimulationLoop::SimulationLoop(const WorldModel& world, const Scenario& scenario,
                               std::vector<GroundPilot>& robots,
                               std::vector<VehiclePilot>& quadrotors,
                               const SimulationOptions& options)
    : world_(world),
      options_(options),
      pilot_(pilotIndices(world, robots.size(), quadrotors.size())),
      d_(mj_makeData(world.model())),
      physics_(world, scenario, options.settings) {
  const mjModel* m = world.model();
  mjData* d = d_.get();
  mj_resetData(m, d);
  for (const auto& v : world.vehicles())
    if (v.drive.planar_root) setPlanarPose(d, v, v.drive.planar_origin, v.drive.start_yaw);
  physics_.startHovering(d);
  if (options_.log_rate > 0.0)
    controls_per_log_ = std::max(
        1, static_cast<int>(std::ceil(1.0 / (options_.log_rate * physics_.controlDt()) - 1e-9)));

  // Moving obstacles: mocap bodies placed from their trajectories.
  if (!options_.obstacle_position)
    options_.obstacle_position = [&scenario](std::size_t i, double t) {
      return movingObstaclePosition(scenario.moving_obstacles[i], t);
    };
  for (std::size_t i = 0; i < scenario.moving_obstacles.size(); ++i) {
    const int body = mj_name2id(m, mjOBJ_BODY, movingObstacleName(i).c_str());
    mocap_.push_back(body >= 0 ? m->body_mocapid[body] : -1);
    MovingObstacleLog& ol = log_.moving_obstacles.emplace_back();
    ol.name = movingObstacleName(i);
    ol.radius = movingObstacleFootprintRadius(scenario.moving_obstacles[i]);
  }
  placeObstacles(0.0);
  mj_forward(m, d);

  beginVehicles(scenario, robots, quadrotors);
  states_.resize(robots.size());
  if (physics_.maxSteps() <= 0) end(RunEnd::MaxTime);
  if (options_.second_thread && !physics_.forcesReadGeometry() && m->opt.integrator != mjINT_RK4) {
    worker_ = std::make_unique<StepWorker>();
    qpos_seen_.resize(m->nq);
    view_ = *d;  // the arrays' addresses, which stay; qpos and time are set at every step
    view_.qpos = qpos_seen_.data();
  }
  if (options_.profile) options_.profile->overlapped = worker_ != nullptr;
  physics_.startClock();
}

SimulationLoop::~SimulationLoop() = default;

void SimulationLoop::beginVehicles(const Scenario& scenario, std::vector<GroundPilot>& robots,
                                   std::vector<VehiclePilot>& quadrotors) {
  const SimSettings& cfg = options_.settings;
  const AerialStepRules rules(cfg, scenario.world, options_.aerial_hold_after_arrival,
                              options_.max_saturated_time);
  const AerialSensing sensing{scenario.sensors, scenario.estimator, cfg.seed};
  const auto& vehicles = world_.vehicles();
  // A modest share of the samples a whole run would log; the logs grow as the vehicles fly.
  const std::size_t most_samples =
      static_cast<std::size_t>(cfg.max_time / (controls_per_log_ * physics_.controlDt())) + 2;
  const std::size_t initial_samples = initialLogSamples(most_samples, vehicles.size());
  for (std::size_t v = 0; v < vehicles.size(); ++v) {
    if (vehicles[v].kind == VehicleKind::GroundRobot) {
      GroundPilotStep& g = drives_.emplace_back(vehicles[v], v, robots[pilot_[v]],
                                                cfg.goal_tolerance, options_.hold_after_arrival);
      log_.vehicles.push_back(g.begin());
    } else {
      AerialPilotStep& f =
          flights_.emplace_back(vehicles[v], quadrotors[pilot_[v]], rules, sensing, v);
      log_.vehicles.push_back(f.begin(d_.get(), initial_samples, most_samples));
    }
  }
}

void SimulationLoop::placeObstacles(double t) {
  for (std::size_t i = 0; i < mocap_.size(); ++i) {
    if (mocap_[i] < 0) continue;
    const Eigen::Vector2d p = options_.obstacle_position(i, t);
    d_->mocap_pos[3 * mocap_[i]] = p.x();
    d_->mocap_pos[3 * mocap_[i] + 1] = p.y();
  }
}

bool SimulationLoop::stepControl() {
  if (done_) return false;
  LoopProfile* profile = options_.profile;
  const double t0 = profile ? seconds() : 0.0;
  const double cpu0 = profile ? LoopProfile::threadCpu() : 0.0;
  std::optional<RunEnd> reason;
  const long last =
      std::min(physics_.stepsTaken() + physics_.stepsPerControl(), physics_.maxSteps());
  if (worker_) {
    reason = prepare();
    control_due_ = true;
    while (!reason && physics_.stepsTaken() < last) reason = overlappedStep();
  } else {
    reason = control();
    while (!reason && physics_.stepsTaken() < last) reason = physicsStep();
  }
  if (profile) {
    profile->wall += seconds() - t0;
    profile->cpu += LoopProfile::threadCpu() - cpu0;
  }
  if (reason) return end(*reason);
  if (physics_.stepsTaken() >= physics_.maxSteps()) return end(RunEnd::MaxTime);
  return true;
}

std::optional<RunEnd> SimulationLoop::physicsStep() {
  placeObstacles(d_->time);
  // (Wind, rotor drag and ground effect act on the quadrotors, also over the robots.)
  LoopProfile* profile = options_.profile;
  if (!profile) return physics_.step(d_.get(), log_);
  double t = seconds();
  physics_.applyForces(d_.get());
  t = lap(t, &profile->forces);
  mj_step(world_.model(), d_.get());
  t = lap(t, &profile->engine);
  const std::optional<RunEnd> fault = physics_.afterStep(d_.get(), log_);
  lap(t, &profile->after_step);
  ++profile->physics_steps;
  return fault;
}

// mj_step is mj_step1 (positions and velocities: kinematics, collisions, inertia, bias forces)
// then mj_step2 (actuation, acceleration, constraints, integration). The controllers and the
// step's forces read only qpos, qvel, qacc, time and their own state, and write only
// qfrc_applied and their own state, which mj_step1 does not read: they run on the second thread
// meanwhile. Of what they read, mj_step1 writes only qpos (its kinematics normalise the
// quaternions in place): the second thread reads a copy taken before (view_). mj_step1 begins
// with MuJoCo's bad-state checks, which may reset the state; they run here first, so that
// mj_step1 finds nothing to change.
std::optional<RunEnd> SimulationLoop::overlappedStep() {
  const mjModel* m = world_.model();
  mjData* d = d_.get();
  placeObstacles(d->time);
  mj_checkPos(m, d);
  mj_checkVel(m, d);
  std::copy(d->qpos, d->qpos + m->nq, qpos_seen_.begin());
  view_.time = d->time;
  control_reason_.reset();
  worker_->start([this] { secondThreadJob(); });
  LoopProfile* profile = options_.profile;
  double t = profile ? seconds() : 0.0;
  mj_step1(m, d);
  if (profile) t = lap(t, &profile->engine);
  worker_->wait();
  if (profile) t = lap(t, &profile->waited);
  if (control_reason_) return control_reason_;
  control_due_ = false;
  mj_step2(m, d);
  if (profile) t = lap(t, &profile->engine);
  const std::optional<RunEnd> fault = physics_.afterStep(d, log_);
  if (profile) {
    lap(t, &profile->after_step);
    ++profile->physics_steps;
  }
  return fault;
}

void SimulationLoop::secondThreadJob() {
  if (control_due_ && (control_reason_ = controlVehicles(&view_))) return;
  LoopProfile* profile = options_.profile;
  const double t = profile ? seconds() : 0.0;
  physics_.applyForces(&view_);
  if (profile) lap(t, &profile->forces);
}

std::optional<RunEnd> SimulationLoop::control() {
  if (const std::optional<RunEnd> reason = prepare()) return reason;
  return controlVehicles(d_.get());
}

std::optional<RunEnd> SimulationLoop::prepare() {
  if (options_.interrupt && options_.interrupt->load()) return RunEnd::Interrupted;
  const mjData* d = d_.get();
  const auto& vehicles = world_.vehicles();
  for (std::size_t v = 0; v < vehicles.size(); ++v)
    if (vehicles[v].kind == VehicleKind::GroundRobot)
      states_[pilot_[v]] = readPlanarState(d, vehicles[v]);
  if (options_.before_control && !options_.before_control(d->time, states_)) return RunEnd::GaveUp;
  return std::nullopt;
}

std::optional<RunEnd> SimulationLoop::controlVehicles(const mjData* d) {
  const auto& vehicles = world_.vehicles();
  LoopProfile* profile = options_.profile;
  const double t0 = profile ? seconds() : 0.0;
  const bool record = control_count_++ % controls_per_log_ == 0;
  const double control_dt = physics_.controlDt();
  bool all_done = true, diverged = false, saturated = false;
  for (std::size_t v = 0; v < vehicles.size(); ++v) {
    VehicleLog& vl = log_.vehicles[v];
    if (vehicles[v].kind == VehicleKind::GroundRobot) {
      const GroundPilotStep::Outcome o =
          drives_[pilot_[v]].step(d, states_[pilot_[v]], physics_, control_dt, vl, record);
      all_done = all_done && o.done;
      diverged = diverged || o.diverged;
    } else {
      const AerialPilotStep::Outcome o =
          flights_[pilot_[v]].step(d, physics_.plant(v), control_dt, vl, record);
      all_done = all_done && o.done;
      diverged = diverged || o.diverged;
      saturated = saturated || o.saturated;
    }
  }
  if (record)
    for (std::size_t i = 0; i < mocap_.size(); ++i) {
      const Eigen::Vector2d p = options_.obstacle_position(i, d->time);
      log_.moving_obstacles[i].t.push_back(d->time);
      log_.moving_obstacles[i].pos.push_back({p.x(), p.y(), 0.0});
    }
  if (profile) {
    const double spent = seconds() - t0;
    profile->controllers += spent;
    ++profile->control_steps;
    if (record) {
      profile->controllers_logged += spent;
      ++profile->logged_steps;
    }
  }
  if (diverged || saturated) return diverged ? RunEnd::Diverged : RunEnd::Saturated;
  if (all_done) return RunEnd::Goal;
  return std::nullopt;
}

bool SimulationLoop::end(RunEnd reason) {
  end_reason_ = reason;
  done_ = true;
  return false;
}

double SimulationLoop::time() const {
  return d_ ? d_->time : end_time_;
}

RunLog SimulationLoop::finish() {
  if (!d_) throw std::logic_error("SimulationLoop::finish called twice");
  if (!done_) end(RunEnd::Interrupted);
  log_.end_reason = end_reason_;
  physics_.finish(d_.get(), log_);
  if (options_.profile)
    for (int i = 0; i < mjNTIMER; ++i) options_.profile->mujoco_ms[i] = d_->timer[i].duration;
  end_time_ = d_->time;
  d_.reset();
  return std::move(log_);
}

RunLog SimulationLoop::snapshot() const {
  if (!d_) throw std::logic_error("SimulationLoop::snapshot after finish");
  RunLog log = log_;
  log.end_reason = end_reason_;
  physics_.finish(d_.get(), log);
  return log;
}

TrueVehicleState SimulationLoop::vehicleState(std::size_t v) const {
  if (!d_) throw std::logic_error("SimulationLoop::vehicleState after finish");
  const VehicleHandles& h = world_.vehicles().at(v);
  TrueVehicleState s;
  if (h.drive.planar_root) {  // the robots' own reader; the body is level, at its fixed height
    const PlanarState p = readPlanarState(d_.get(), h);
    s.position = {p.position.x(), p.position.y(), world_.model()->body_pos[3 * h.body + 2]};
    s.velocity = {p.velocity.x(), p.velocity.y(), 0.0};
    s.quaternion = {std::cos(0.5 * p.yaw), 0.0, 0.0, std::sin(0.5 * p.yaw)};
    s.angular_velocity = {0.0, 0.0, p.yaw_rate};
    return s;
  }
  // Free joint: x y z qw qx qy qz; linear velocity in the world, angular in the body frame.
  const mjtNum* q = d_->qpos + h.qpos_adr;
  const mjtNum* u = d_->qvel + h.qvel_adr;
  s.position = {q[0], q[1], q[2]};
  s.velocity = {u[0], u[1], u[2]};
  s.quaternion = {q[3], q[4], q[5], q[6]};
  s.angular_velocity = {u[3], u[4], u[5]};
  return s;
}

}  // namespace cosim
