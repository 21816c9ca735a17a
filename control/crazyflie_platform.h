#pragma once
// What crazyflie-firmware knows of the vehicle it is built for, and what its stabilizer does with
// a controller's output before the motors turn: the Crazyflie 2.1 Brushless build's platform
// defaults (CONFIG_PLATFORM_CF21BL with the default battery compensation), its power
// distribution and its motor capping. The firmware's code is not used; its parameter values are
// taken as facts, each cited by file and name in crazyflie_platform.cpp.
//
// The thrust command path, as the firmware does it (power_distribution_quadrotor.c, stabilizer.c,
// motors.c), per stabilizer step:
//  1. power distribution: a force/torque command (Lee) becomes per-motor forces
//       f_i = T/4 -+ tau_x / (4 l / sqrt 2) -+ tau_y / (4 l / sqrt 2) -+ tau_z / (4 k)
//     (l = ARM_LENGTH, k = THRUST2TORQUE), each floored at 0; a legacy command (PID, Mellinger:
//     thrust, roll, pitch, yaw in the 16-bit PWM scale) becomes u_i = T -+ roll/2 -+ pitch/2 -+
//     yaw, whose force is u_i / 65535 THRUST_MAX;
//  2. battery compensation: the motor voltage that makes f_i by the platform's thrust curve
//     f = c0 + c1 v + c2 v^2 + c3 v^3 (VMOTOR2THRUST0..3), over the supply voltage, is the duty
//     cycle; a force below THRUST_MIN gives duty 0 (the motor stops);
//  3. capping: if the highest duty exceeds full scale, every motor's duty drops by the excess
//     (keeping the differences, i.e. the torques, and giving up collective thrust).
// The simulated motor then makes the thrust-curve force of its duty cycle's voltage. The supply
// voltage at which full duty makes the rotors' maximum thrust (k_f w_max^2 of the airframe) is the
// one taken, so the firmware's cap and the rotors' speed limit coincide.
#include <Eigen/Core>

namespace cosim {

struct CrazyfliePlatform {
  // CF_MASS, kg: the firmware's default ctrlLee.mass / ctrlMel.mass, which its documentation
  // asks users to update to their vehicle's mass. cosim's Lee and Mellinger believe the given
  // airframe's mass instead; this is the value that models a firmware left unconfigured.
  double mass;
  double arm_length;              // ARM_LENGTH, m, centre to motor
  double thrust_to_torque;        // THRUST2TORQUE, m
  double thrust_max;              // THRUST_MAX, N per motor at 65535 of the thrust scale
  double thrust_min;              // THRUST_MIN, N per motor: below it the motor is off
  Eigen::Vector4d vmotor2thrust;  // VMOTOR2THRUST0..3: N per motor from motor volts
  double gravity;                 // GRAVITY_MAGNITUDE, m/s^2
};

// The Crazyflie 2.1 Brushless build's defaults.
CrazyfliePlatform crazyflie21BrushlessPlatform();

// Steps 2-3 and the motors' response. Motor order is the firmware's: M1 front right, M2 back
// right, M3 back left, M4 front left (x forward, y left, z up).
class CrazyflieMotors {
 public:
  // max_rotor_thrust: each rotor's thrust at full duty (k_f w_max^2), N; infinite: no cap.
  CrazyflieMotors(const CrazyfliePlatform& platform, double max_rotor_thrust);

  // The thrust each motor makes for the requested forces (N, firmware order), after battery
  // compensation and capping; *capped is set when the firmware had to cap.
  Eigen::Vector4d deliver(const Eigen::Vector4d& requested, bool* capped) const;

  // The platform's thrust curve and its inverse (motor volts <-> N).
  double thrustAtVoltage(double volts) const;
  double voltageForThrust(double thrust) const;
  const CrazyfliePlatform& platform() const { return p_; }
  // The motor volts at full duty (infinite: no cap).
  double fullScaleVolts() const { return full_scale_volts_; }

 private:
  // Newton's method on the thrust curve for `thrust`, from v (any v >= 0).
  double newtonFrom(double v, double thrust) const;

  CrazyfliePlatform p_;
  double full_scale_volts_;   // motor volts at full duty (infinite: no cap)
  double full_scale_thrust_;  // the thrust at full duty (infinite: no cap)
  // The curve's inverse at evenly spaced thrusts, the start of voltageForThrust's iteration.
  static constexpr int kTableSize = 257;
  double table_step_ = 0.0;
  double table_[kTableSize] = {};
};

// Step 1, force/torque mode (controlModeForceTorque): per-motor forces, N, firmware order.
Eigen::Vector4d crazyflieForceTorqueMix(const CrazyfliePlatform& p, double thrust,
                                        const Eigen::Vector3d& torque);
// Step 1, legacy mode (controlModeLegacy): thrust, roll, pitch, yaw on the 16-bit scale, with
// the firmware's signs (roll right-handed about x, pitch positive nose up, yaw positive
// clockwise seen from above); per-motor forces, N, firmware order.
Eigen::Vector4d crazyflieLegacyMix(const CrazyfliePlatform& p, double thrust, double roll,
                                   double pitch, double yaw);

// Firmware motor order (M1..M4) to cosim's rotor order (rotor i at 45 + 90 i degrees: front
// left, rear left, rear right, front right; models/cf2.xml and cf21_brushless.xml).
Eigen::Vector4d crazyflieToRotorOrder(const Eigen::Vector4d& m);

// The firmware's stabilizer clock: 1000 Hz ticks, the controllers' parts at 500 Hz
// (ATTITUDE_RATE) and 100 Hz (POSITION_RATE, RATE_HL_COMMANDER). cosim calls a controller every
// control period; this counts the ticks that period covers and says which parts are due.
class CrazyflieClock {
 public:
  void reset();
  // Advances by dt (the first call after reset is tick 0); true if a part at rate_hz runs now.
  void advance(double dt);
  bool due(double rate_hz) const;

 private:
  double time_ = 0.0;
  bool started_ = false;
  long long previous_tick_ = -1, tick_ = 0;
};

}  // namespace cosim
