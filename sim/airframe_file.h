#pragma once
// vehicles[i].airframe: a YAML file of airframe parameters, as `cosim identify` writes them
// (docs/identify.md), that replace the model file's constants for that vehicle. Each key is a
// number or a mapping whose `value` is the number (the identified file's ci95, residual,
// residual_unit, unit and samples are read past). Every key is optional:
//   mass (kg)                         the flown total, as vehicles[i].mass (which wins if given)
//   thrust_coefficient (N/(rad/s)^2)  k_f
//   time_constant_up, time_constant_down (s)  the rotor's first-order lag (sim/rotor_model.h)
//   motor_delay (s)                   a pure delay before the lag
//   rotor_drag_coefficient (N/(m/s)/(rad/s))  sim/rotor_aerodynamics.cpp's c_d
//   gyro_noise (rad/s/sqrt(Hz)), accel_noise (m/s^2/sqrt(Hz))  this vehicle's IMU densities
//   motor_speed_coefficients [c0, c1, c2]  omega_ss = c0 + c1 v + c2 v^2 (rad/s),
//                                     v = PWM / 65535 V_battery: the motor map of a vehicle
//                                     flown on a battery (vehicles[i].battery).
// Bad input (a missing file, an unknown key, a value out of range) is an InputError naming the
// airframe file, the line and the key.
#include <array>
#include <filesystem>
#include <optional>

namespace cosim {

struct QuadrotorParams;

struct AirframeFile {
  std::filesystem::path file;  // empty: the vehicle has none
  std::optional<double> mass, thrust_coefficient, time_constant_up, time_constant_down, motor_delay,
      rotor_drag_coefficient, gyro_noise, accel_noise;
  std::optional<std::array<double, 3>> motor_speed_coefficients;
};

AirframeFile readAirframeFile(const std::filesystem::path& path);

// The rotor constants of `a` put into `p` (k_f, time constants, delay, rotor drag, motor map); the mass
// goes through vehicles[i].mass, the IMU densities through the vehicle's plant.
void applyAirframeFile(const AirframeFile& a, QuadrotorParams& p);

}  // namespace cosim
