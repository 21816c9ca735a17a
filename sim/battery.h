#pragma once
// A quadrotor's 1S LiPo battery (vehicles[i].battery): an open-circuit voltage over the state of
// charge behind an internal resistance (the Thevenin model without its RC pair: the voltage
// sags with the current at once and recovers at once), draining by the current the rotors draw.
//
// Open-circuit voltage: crazyflie-firmware src/hal/src/pm_stm32f4.c, LiPoTypicalChargeCurve
// (the firmware's own charge curve for the Crazyflie's LiPo: 3.00, 3.78, 3.83, 3.87, 3.89, 3.92,
// 3.96, 4.00, 4.04, 4.10 V at 0, 10, ..., 90 %), and 4.20 V at 100 % (motors.c: "A LiPo battery
// is supposed to be 4.2V charged, 3.7V mid-charge and 3V discharged"), linear between them.
//
// The current: the rotors' shaft power, sum of tau_i w_i with the reaction torque
// tau = (k_m / k_f) k_f w^2 of the airframe, over the drive's efficiency eta (ESC and motor),
// P = sum (k_m/k_f) k_f w_i^3 / eta; the battery delivers P at its terminal voltage V = OCV - I R,
// I = P / V, so V = (OCV + sqrt(OCV^2 - 4 R P)) / 2 (the upper root; past OCV^2 / 4R, the most
// a source of resistance R delivers, V = OCV / 2).
//
// Defaults (the Crazyflie 2.1 Brushless):
//  - capacity 350 mAh: Bitcraze's specification of the Brushless ("Weight: 32 grams (including
//    350mAh battery)");
//  - R / eta = 0.169 ohm: least-squares fit of V = a + b k - (R / eta) P_shaft / V to the
//    thrust stand's battery voltage over its 72 rows k (IMRCLab crazyflie-data-collection
//    system-id/data/cf21bl_guards/feb25_2026_0.csv, the shaft power from its mean rpm through
//    k_f 3.86e-8 and THRUST2TORQUE 0.00569278844371417; a + b k: the open-circuit voltage falling
//    over the test; residual 0.032 V rms). The stand has no current column, so only the ratio is
//    identified: eta = 0.5 is an estimate (no measured efficiency of these motors and ESCs in the
//    sources used), giving R = 0.085 ohm; eta sets only how fast the charge drains, the ratio
//    alone the voltage sag.
#include <array>

namespace cosim {

struct BatterySettings {
  double capacity_mah = 350.0;         // mAh
  double state_of_charge = 1.0;        // at the start, 0..1
  double internal_resistance = 0.085;  // ohm (battery, connector and power path)
  double drive_efficiency = 0.5;       // electrical to shaft power of the ESCs and motors, 0..1

  // The keys of vehicles[i].battery (sim/declared_keys.h).
  template <class Visitor>
  void declareKeys(Visitor& v) {
    v.number("capacity_mah", capacity_mah, 1.0, 1e6, "mAh");
    v.number("state_of_charge", state_of_charge, 0.0, 1.0, "at the start, 0 (empty) to 1 (full)");
    v.number("internal_resistance", internal_resistance, 0.0, 10.0,
             "ohm, battery, connector and power path");
    v.number("drive_efficiency", drive_efficiency, 0.01, 1.0,
             "electrical to shaft power of the ESCs and motors");
  }
};

class LipoBattery {
 public:
  explicit LipoBattery(const BatterySettings& settings);

  // The open-circuit voltage at a state of charge (clamped to 0..1), V.
  static double openCircuitVoltage(double state_of_charge);
  // The terminal voltage delivering `current` (A): OCV - I R.
  double terminalVoltage(double current) const;
  // The terminal voltage delivering `power` (W): the upper root of V^2 - OCV V + R P = 0.
  double terminalVoltageAtPower(double power) const;
  // Draws `current` (A) for dt seconds (the charge stops at empty).
  void drain(double current, double dt);

  double stateOfCharge() const { return state_of_charge_; }
  const BatterySettings& settings() const { return settings_; }

 private:
  BatterySettings settings_;
  double state_of_charge_;
};

}  // namespace cosim
