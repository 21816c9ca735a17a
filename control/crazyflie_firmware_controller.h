#pragma once
// What the three crazyflie-firmware controllers (crazyflie_lee, crazyflie_mellinger,
// crazyflie_pid) share: the stabilizer's clock and the path from their output to the motors.
// cosim calls a controller every control period (sim.control_rate, a multiple of 500 Hz for
// these); the firmware's own rates hold whatever that period is:
//  - the high-level commander evaluates the trajectory at 100 Hz (RATE_HL_COMMANDER): the
//    reference is sampled at those ticks and held in between;
//  - the control law runs at 500 Hz (ATTITUDE_RATE); the PID's position loop at 100 Hz
//    (POSITION_RATE) inside it;
//  - its output goes through the platform's power distribution, battery compensation and
//    capping (control/crazyflie_platform.h) to the thrust each motor makes, held until the next
//    law step; on a vehicle that carries a battery (VehicleState::battery_voltage > 0), or with
//    the fork's pwm_quadratic thrust map, to each motor's duty cycle instead
//    (control/crazyflie_thrust_path.h), which the simulated motors turn into rotor speed on the
//    battery's voltage.
#include "control/crazyflie_platform.h"
#include "control/crazyflie_thrust_path.h"
#include "control/flight_controller.h"
#include "control/mixer.h"

namespace cosim {

class CrazyflieFirmwareController : public FlightController {
 public:
  // airframe: what the flight software's motor model needs of the vehicle, i.e. each rotor's
  // thrust at full duty (max_thrust); the control laws use the platform's own constants.
  CrazyflieFirmwareController(const QuadrotorParams& airframe, const CrazyfliePlatform& platform);
  void reset() override;
  ControlOutput update(const VehicleState& state, const FlatReference& ref, double dt) override;
  // The build's thrust path (thrust map, idle thrust, the power distribution's platform
  // constants); the default is upstream's Brushless build. Call before flying.
  void setThrustPath(const CrazyflieThrustPath& path);

 protected:
  // Per-motor forces, N, firmware order (M1..M4), from the law's 500 Hz step. `clock` says
  // whether slower parts (the PID's 100 Hz position loop) are due at this step.
  virtual Eigen::Vector4d lawStep(const VehicleState& state, const FlatReference& setpoint,
                                  const CrazyflieClock& clock) = 0;
  virtual void resetLaw() = 0;
  // True for a law in the firmware's legacy control mode (thrust, roll, pitch, yaw on the 16-bit
  // scale: Mellinger, PID), false in force/torque mode (Lee).
  virtual bool legacyMode() const = 0;

  CrazyfliePlatform platform_;  // the build's, with the power distribution's platform constants

 private:
  // The motors' forces from the law's (firmware order), delivered into output_.
  void deliver(const Eigen::Vector4d& forces, double battery_voltage);
  // On a battery: each motor's duty cycle (firmware order) for the law's forces.
  Eigen::Vector4d motorDuties(const Eigen::Vector4d& forces, double battery_voltage,
                              bool* capped) const;

  CrazyfliePlatform build_platform_;  // as given, before the thrust path's mixer constants
  CrazyflieThrustPath path_;
  CrazyflieMotors motors_;
  double idle_force_ = 0.0;  // without a battery: the thrust of the idle PWM at full-scale volts
  Mixer mixer_;  // the airframe's geometry, for the wrench the delivered thrusts make (logging)
  CrazyflieClock clock_;
  FlatReference setpoint_;
  ControlOutput output_;
};

// A firmware law with its gain set (`Gains`, which has a `mass` field, kg) and the mass it
// believes: gains.mass if positive, else the mass of the airframe the controller is given (the
// vehicle's mass, times model_error.mass if set). crazyflie-firmware's platform_defaults_cf21bl.h
// says of CF_MASS (0.0393 kg) "Default: Crazyflie 2.1 Brushless with propeller guards, 350mAh
// battery, and Lighthouse deck. Update this value with the mass of your specific setup if
// different", through CONFIG_MODIFIED_CF_MASS or the controller's mass parameter (ctrlLee.mass,
// ctrlMel.mass); a scenario that states the flown mass describes a firmware configured as asked.
// A firmware left at its default on a vehicle of another mass is gains {mass: 0.0393} (or
// model_error.mass).
template <class Gains>
class CrazyflieMassBasedController : public CrazyflieFirmwareController {
 protected:
  CrazyflieMassBasedController(const QuadrotorParams& airframe, const Gains& gains,
                               const CrazyfliePlatform& platform)
      : CrazyflieFirmwareController(airframe, platform),
        gains_(gains),
        mass_(gains.mass > 0.0 ? gains.mass : airframe.mass) {}

  Gains gains_;
  double mass_;  // kg
};

// controller.gains.mass (ctrlLee.mass, ctrlMel.mass), when given: a real vehicle's mass, kg, from
// a third of the 27 g Crazyflie 2.1 (the lightest model) to 100 kg. Absent, the airframe's mass
// (the struct's -1); zero or a negative value is refused, not taken as "the airframe's".
constexpr double kBelievedMassMin = 0.01;
constexpr double kBelievedMassMax = 100.0;

// The body rates the high-level commander puts into the setpoint (attitudeRate), from the
// reference by differential flatness (pptraj.c, after Mellinger and Kumar 2011 eq. 7):
// z_b = (a + g e3) / |a + g e3|, x from the yaw, h = (j - (j . z_b) z_b) / |a + g e3|,
// w = (-h . y_b, h . x_b, z_b,z yaw_rate), rad/s.
Eigen::Vector3d highLevelCommanderRates(const FlatReference& ref, double gravity);

// The law's step length: 1 / ATTITUDE_RATE.
constexpr double kCrazyflieAttitudeRate = 500.0;  // Hz, stabilizer_types.h ATTITUDE_RATE
constexpr double kCrazyfliePositionRate = 100.0;  // Hz, stabilizer_types.h POSITION_RATE

}  // namespace cosim
