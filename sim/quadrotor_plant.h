#pragma once
// The parts of a quadrotor between the rigid body MuJoCo integrates and the flight software:
// its four rotors (sim/rotor_model.h), its battery if it has one (sim/battery.h), and the sensors
// it carries (sim/sensors/). The physics owns
// them (sim/physics_stepper.h): the rotors advance and the sensors sample the true state at every
// physics step, each sensor at its own rate, and a measurement waits its latency before the
// estimator may have it (takeDelivered).
#include <mujoco/mujoco.h>

#include <cstdint>
#include <deque>
#include <memory>
#include <optional>
#include <vector>

#include "sim/battery.h"
#include "sim/rotor_model.h"
#include "sim/sensors/imu_sensor.h"
#include "sim/sensors/pose_sensor.h"
#include "sim/sensors/sensor_settings.h"
#include "sim/world_model.h"

namespace cosim {

// Measurements handed over at one control step, each list in order of validity time.
struct SensorReadings {
  std::vector<ImuMeasurement> imu;
  std::vector<PositionMeasurement> position;
  std::vector<AttitudeMeasurement> attitude;
};

// A seed for one sensor of one vehicle, derived from the scenario's seed (splitmix64), so that
// every stream is independent and a run is repeatable.
std::uint64_t sensorSeed(std::uint64_t scenario_seed, std::size_t vehicle, int sensor);

class QuadrotorPlant {
 public:
  // battery: vehicles[i].battery (nullptr: an ideal supply; the rotors follow speed commands).
  QuadrotorPlant(const VehicleHandles& vehicle, const SensorSettings& sensors,
                 std::uint64_t scenario_seed, std::size_t vehicle_index,
                 const BatterySettings* battery = nullptr);

  RotorModel& rotors() { return rotors_; }
  const RotorModel& rotors() const { return rotors_; }

  // With a battery the flight software drives the motors by duty cycle (0..1, cosim's rotor
  // order): at every physics step each rotor is commanded the motor's steady-state speed for its
  // duty at the battery's terminal voltage then (QuadrotorParams::steadyRotorSpeed), through the
  // rotors' lag, so the thrust follows the voltage as it sags.
  void commandDuties(const Eigen::Vector4d& duty);
  // One physics step of the rotors (and the battery: its voltage at the rotors' power, the
  // commands from the duty cycles, then the charge drained by the current).
  void advanceRotors(double dt);
  bool hasBattery() const { return battery_.has_value(); }
  // The battery's terminal voltage at the rotors' present power (V); 0 without a battery.
  double batteryVoltage() const;
  // The electrical power the rotors draw (W): sum (k_m/k_f) k_f w^3 / drive efficiency.
  double electricalPower() const;
  const std::optional<LipoBattery>& battery() const { return battery_; }
  // The thrust each rotor applied in the last physics step (its k_f w^2 times the ground-effect
  // and downwash factors; sim/aerodynamics.h sets it), N.
  const Eigen::Vector4d& appliedThrusts() const { return applied_; }
  void setAppliedThrusts(const Eigen::Vector4d& thrusts) { applied_ = thrusts; }

  // After mj_step: every sensor whose next sample is due measures the state at d->time.
  void sense(const mjData* d);
  // The measurements whose latency has passed by `now`, removed from the queue, into `out`
  // (cleared first): the caller keeps one `out` for the run, so that handing over the readings
  // of a control step allocates nothing once the lists have grown to their size.
  void takeDelivered(double now, SensorReadings& out);
  // True specific force (acceleration minus gravity) in the body frame, from MuJoCo's last
  // acceleration (what a perfect accelerometer would read).
  Eigen::Vector3d trueSpecificForce(const mjData* d) const;

 private:
  struct Due {
    double next = 0.0;    // s, time of the next sample
    double period = 0.0;  // s
    bool at(double t) const { return t >= next - 1e-9; }
  };
  const VehicleHandles* vehicle_;
  double gravity_;
  RotorModel rotors_;
  std::optional<LipoBattery> battery_;
  Eigen::Vector4d duty_ = Eigen::Vector4d::Zero();
  bool duty_commanded_ = false;  // false until the flight software first commands duty cycles
  Eigen::Vector4d applied_ = Eigen::Vector4d::Zero();
  std::unique_ptr<ImuSensor> imu_;
  std::unique_ptr<PositionSensor> position_;
  std::unique_ptr<AttitudeSensor> attitude_;
  Due imu_due_, position_due_, attitude_due_;
  double position_latency_ = 0.0, attitude_latency_ = 0.0;
  SensorReadings ready_;  // delivered on the next takeDelivered (the IMU has no latency)
  std::deque<PositionMeasurement> position_queue_;
  std::deque<AttitudeMeasurement> attitude_queue_;
};

}  // namespace cosim
