#pragma once
// The configurations `cosim reproduce crazyflie-figure8` flies: the bundled
// experiments/scenarios/crazyflie_figure8.yaml under each firmware controller, and under
// crazyflie_lee with one effect of the rig as flown switched off at a time (and all of them at
// once), so that the study can say which effect makes the real vehicle lag and under-shoot.
#include <cstdint>
#include <string>

#include "control/crazyflie_lee_controller.h"
#include "control/crazyflie_mellinger_controller.h"
#include "control/crazyflie_pid_controller.h"
#include "sim/scenario.h"

namespace cosim::reproduce {

// The effects of the rig as flown that a variant can switch off (a bit each).
enum FigureEightEffect : unsigned {
  kNoEffectOff = 0,
  kSensing = 1u << 0,            // mocap and the estimator: the controller reads the true state
  kThrustLimit = 1u << 1,        // the rotors' speed limit (and so the firmware's capping)
  kRotorDrag = 1u << 2,          // rotor drag
  kMotorLag = 1u << 3,           // the motors' delay and first-order lag
  kFirmwareEstimator = 1u << 4,  // crazyflie_kalman: flown with the EKF instead
  kBatterySag = 1u << 5,         // the battery's sag and drain: a stiff, endless one instead
  kImuNoise = 1u << 6,           // IMU noise and biases
  kMocapLatency = 1u << 7,       // the poses' 11 ms from the cameras to the vehicle
};

struct FigureEightVariant {
  const char* label;       // the row's "controller"
  const char* controller;  // controller.name
  unsigned effects_off = kNoEffectOff;
  // The firmware left unconfigured: ctrlLee.mass at CF_MASS (39.3 g) instead of the flown mass.
  bool firmware_default_mass = false;
};

constexpr char kFirmwareDefaultMass[] = "lee/firmware_default_mass";

// The controller columns, then the effect rows (crazyflie_lee with one effect off; the last,
// every effect off at once).
inline constexpr FigureEightVariant kFigureEightControllers[] = {
    {CrazyflieLeeController::kName, CrazyflieLeeController::kName},
    {CrazyflieMellingerController::kName, CrazyflieMellingerController::kName},
    {CrazyfliePidController::kName, CrazyfliePidController::kName},
    {kFirmwareDefaultMass, CrazyflieLeeController::kName, kNoEffectOff, true}};

inline constexpr FigureEightVariant kFigureEightEffects[] = {
    {"lee/ideal_sensing", CrazyflieLeeController::kName, kSensing},
    {"lee/ekf_estimator", CrazyflieLeeController::kName, kFirmwareEstimator},
    {"lee/no_mocap_latency", CrazyflieLeeController::kName, kMocapLatency},
    {"lee/no_imu_noise", CrazyflieLeeController::kName, kImuNoise},
    {"lee/no_battery_sag", CrazyflieLeeController::kName, kBatterySag},
    {"lee/no_rotor_drag", CrazyflieLeeController::kName, kRotorDrag},
    {"lee/no_motor_lag", CrazyflieLeeController::kName, kMotorLag},
    {"lee/unlimited_thrust", CrazyflieLeeController::kName, kThrustLimit},
    {"lee/all_off", CrazyflieLeeController::kName,
     kSensing | kThrustLimit | kRotorDrag | kMotorLag | kFirmwareEstimator | kBatterySag |
         kImuNoise | kMocapLatency}};

// The bundled scenario at `timescale` under v's controller, with v's effects off.
Scenario figureEightScenario(const FigureEightVariant& v, double timescale, std::uint64_t seed);

// The composed MuJoCo model of `s` with v's model-level effects off (the rotor speed limit).
std::string figureEightModelXml(const FigureEightVariant& v, const Scenario& s);

}  // namespace cosim::reproduce
