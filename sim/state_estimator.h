#pragma once
// What a quadrotor's flight controller is told of its own state (VehicleState), at each control
// step: with `estimator: ground_truth` the exact state MuJoCo holds (no noise, no delay: the
// "ideal" sensing of earlier rounds); with `estimator: ekf` the estimate of an error-state EKF
// (estimation/) fed by the vehicle's sensors (sim/quadrotor_plant.h), with their noise and
// latency; with `estimator: crazyflie_kalman` the estimate of the Crazyflie firmware's own Kalman
// estimator (estimation/crazyflie_kalman_estimator.h) fed by the same sensors. Either way the
// rotor-thrust feedback is each rotor's true speed through the flight software's own thrust
// coefficient (k_f' w^2), as a rotor-speed sensor would report it.
#include <mujoco/mujoco.h>

#include <cstdint>
#include <memory>

#include "control/flight_controller.h"
#include "control/quadrotor_params.h"
#include "sim/quadrotor_plant.h"
#include "sim/sensors/sensor_settings.h"
#include "sim/world_model.h"

namespace cosim {

class LatencyCompensatedEkf;
class CrazyflieKalmanEstimator;

// The exact state of a vehicle's free body (position, velocity, attitude, body rates).
VehicleState readVehicleState(const mjData* d, const VehicleHandles& v);

class StateEstimator {
 public:
  // `airframe`: what the flight software believes (sim/model_error.h).
  StateEstimator(const EstimatorSettings& estimator, const SensorSettings& sensors,
                 const QuadrotorParams& airframe, std::uint64_t scenario_seed,
                 std::size_t vehicle_index);
  ~StateEstimator();
  StateEstimator(StateEstimator&&) noexcept;
  StateEstimator& operator=(StateEstimator&&) noexcept;

  // Starts the estimate from the vehicle's state at d->time (an EKF from the truth plus an error
  // drawn from its initial covariance, so that the filter's first claims are honest).
  void begin(const mjData* d, const VehicleHandles& v);
  // The controller's view at d->time, after fusing whatever the sensors have delivered.
  VehicleState estimate(const mjData* d, const VehicleHandles& v, QuadrotorPlant& plant);
  bool filtered() const { return ekf_ != nullptr || kalman_ != nullptr; }

 private:
  void beginCrazyflieKalman(const mjData* d, const VehicleHandles& v);
  // The estimate of crazyflie_kalman (rotor thrusts left to estimate()).
  VehicleState estimateCrazyflieKalman(const mjData* d, QuadrotorPlant& plant);

  QuadrotorParams airframe_;
  SensorSettings sensors_;
  std::uint64_t seed_;
  double position_std_;  // the fixes' assumed standard deviations (0: the sensors' noise)
  double attitude_std_;
  std::unique_ptr<LatencyCompensatedEkf> ekf_;
  std::unique_ptr<CrazyflieKalmanEstimator> kalman_;
  bool imu_seen_ = false;
  ImuMeasurement latest_imu_;  // the latest sample delivered (crazyflie_kalman's rates and force)
  SensorReadings readings_;    // one control step's hand-over, reused (no allocation per step)
};

}  // namespace cosim
