#include "sim/battery.h"

#include <algorithm>
#include <cmath>

namespace cosim {

namespace {
// crazyflie-firmware pm_stm32f4.c LiPoTypicalChargeCurve (0 .. 90 % in steps of 10 %), and 4.2 V
// charged (motors.c, motorsCompensateBatteryVoltage's comment).
constexpr std::array<double, 11> kOpenCircuitVolts = {3.00, 3.78, 3.83, 3.87, 3.89, 3.92,
                                                      3.96, 4.00, 4.04, 4.10, 4.20};
}  // namespace

LipoBattery::LipoBattery(const BatterySettings& settings)
    : settings_(settings), state_of_charge_(std::clamp(settings.state_of_charge, 0.0, 1.0)) {}

double LipoBattery::openCircuitVoltage(double state_of_charge) {
  const double x = std::clamp(state_of_charge, 0.0, 1.0) * 10.0;
  const int i = std::min(static_cast<int>(x), 9);
  return kOpenCircuitVolts[i] + (x - i) * (kOpenCircuitVolts[i + 1] - kOpenCircuitVolts[i]);
}

double LipoBattery::terminalVoltage(double current) const {
  return openCircuitVoltage(state_of_charge_) - current * settings_.internal_resistance;
}

double LipoBattery::terminalVoltageAtPower(double power) const {
  const double ocv = openCircuitVoltage(state_of_charge_);
  const double discriminant =
      ocv * ocv - 4.0 * settings_.internal_resistance * std::max(power, 0.0);
  return 0.5 * (ocv + std::sqrt(std::max(discriminant, 0.0)));
}

void LipoBattery::drain(double current, double dt) {
  const double coulombs = settings_.capacity_mah * 3.6;  // 1 mAh = 3.6 C
  state_of_charge_ = std::max(state_of_charge_ - current * dt / coulombs, 0.0);
}

}  // namespace cosim
