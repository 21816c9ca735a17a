#pragma once
// System identification of a quadrotor from its logs (cosim identify, docs/identify.md): the
// motor map PWM and battery voltage -> steady rotor speed, the thrust constant, the motor's
// delay and time constants, the rotor drag, the IMU's noise densities in hover and the mass
// from the hover thrust, each with its 95 % interval and residual; and, when a log has the
// controller's desired and actual attitude, how well the attitude follows its command.
#include <array>
#include <vector>

#include "experiments/identify/identification_log.h"
#include "experiments/identify/identified_value.h"

namespace cosim {

struct IdentifyOptions {
  // A cable-suspended payload's mass (kg): its cable's pull m_p (a_p + g) is taken off the
  // vehicle's hover thrust and specific force (needs the payload's velocity in the log).
  double payload_mass = 0.0;
  // Values to use instead of identifying them (0: identify), e.g. k_f from a thrust stand
  // identified earlier when only flight logs are given.
  double thrust_coefficient = 0.0;
  double mass = 0.0;
  // A vehicle hovers where its speed stays below this (m/s) for at least min_hover_s.
  double hover_speed = 0.1;
  double min_hover_s = 1.0;
  // Which logs the motor map is fitted on: Auto takes the flights (timed logs) when there are
  // any, else the thrust stand's rows (logs without time). A stand driven through another PWM
  // path than the flight's (a power setpoint before the firmware's compensation, say) maps PWM
  // to speed otherwise than the vehicle does in flight.
  enum class MotorMapLogs { Auto, Flight, Stand } motor_map_logs = MotorMapLogs::Auto;
  // Delays searched by the motor fit, s.
  double max_motor_delay = 0.06;
  double gravity = 9.81;
};

struct AttitudeTracking {
  IdentifiedValue gain, lag;  // actual ~ gain * desired(t - lag), per axis
};

struct IdentificationResult {
  std::vector<std::string> logs;
  // omega_ss = c0 + c1 v + c2 v^2, v = PWM / 65535 * V_battery (rad/s, v in volts).
  std::array<IdentifiedValue, 3> motor_speed;
  IdentifiedValue thrust_coefficient;                                 // N / (rad/s)^2
  IdentifiedValue motor_delay, time_constant_up, time_constant_down;  // s
  IdentifiedValue mass;                                               // kg
  IdentifiedValue rotor_drag;                                         // N / (m/s) / (rad/s)
  IdentifiedValue gyro_noise;                                         // rad/s/sqrt(Hz)
  IdentifiedValue accel_noise;                                        // m/s^2/sqrt(Hz)
  AttitudeTracking roll, pitch;
  std::vector<FitFigure> figures;
};

// Identifies everything `logs` allow (bad logs were rejected while reading). A fit the logs do
// not allow is left unidentified with the reason in its not_why.
IdentificationResult identify(const std::vector<IdentificationLog>& logs,
                              const IdentifyOptions& options);

// The fits, each on every log that has its columns (experiments/identify/*_fit.cpp).
void fitMotorMap(const std::vector<IdentificationLog>& logs, const IdentifyOptions& o,
                 IdentificationResult& r);
void fitThrustCoefficient(const std::vector<IdentificationLog>& logs, IdentificationResult& r);
void fitMotorLag(const std::vector<IdentificationLog>& logs, const IdentifyOptions& o,
                 IdentificationResult& r);
void fitHoverMass(const std::vector<IdentificationLog>& logs, const IdentifyOptions& o,
                  IdentificationResult& r);
void fitRotorDrag(const std::vector<IdentificationLog>& logs, const IdentifyOptions& o,
                  IdentificationResult& r);
void fitImuNoise(const std::vector<IdentificationLog>& logs, const IdentifyOptions& o,
                 IdentificationResult& r);
void fitAttitudeTracking(const std::vector<IdentificationLog>& logs, IdentificationResult& r);

// omega_ss of the identified motor map at duty `pwm` / 65535 and battery `vbat`.
double steadyRotorSpeed(const IdentificationResult& r, double pwm, double vbat);

}  // namespace cosim
