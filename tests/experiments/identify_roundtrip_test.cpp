// Acceptance of cosim identify: logs written by the simulator's own models (the rotor model
// with its delay and lag, the rotor drag, the IMU) with known, non-default parameters are
// identified back: mass and k_f within 2 %, rotor drag, motor time constants, delay and noise
// densities within 10 %. The logs go through the CSV reader with named columns, as a user's.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <random>

#include "experiments/identify/identification.h"
#include "experiments/identify/identification_report.h"
#include "sim/airframe_file.h"
#include "sim/rotor_aerodynamics.h"
#include "sim/rotor_model.h"
#include "sim/sensors/imu_sensor.h"
#include "tests/support/test_files.h"

using namespace cosim;

namespace {

// The vehicle the logs are written for: none of these is a model's default.
struct Truth {
  double mass = 0.0412;                              // kg
  double k_f = 4.1e-8;                               // N/(rad/s)^2
  double c0 = 150.0, c1 = 750.0, c2 = -15.0;         // omega_ss(v), rad/s
  double tau_up = 0.022, tau_down = 0.041;           // s
  double delay = 0.008;                              // s
  double drag = 1.3e-6;                              // N/(m/s)/(rad/s)
  double gyro_noise = 2.0e-3, accel_noise = 1.0e-2;  // per sqrt(Hz)
  double g = 9.81;
  double omegaSs(double v) const { return c0 + c1 * v + c2 * v * v; }
  // The motor voltage that makes omega_ss = w (the map's rising root).
  double voltageFor(double w) const {
    return (-c1 + std::sqrt(c1 * c1 - 4.0 * c2 * (c0 - w))) / (2.0 * c2);
  }
};

constexpr double kLogPeriod = 0.002;  // 500 Hz, the Crazyflie's fixed-frequency log
constexpr double kRpm = 60.0 / (2.0 * M_PI);

// A thrust stand: PWM and voltage spread over the range, rpm and the total thrust.
void writeStandLog(const Truth& tr, const std::filesystem::path& file) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> pwm(12000.0, 62000.0), vbat(3.3, 4.1);
  std::normal_distribution<double> scale_noise(0.0, 0.004);  // N, a load cell
  std::ofstream out(file);
  out << "pwm,vbat[V],rpm1,rpm2,rpm3,rpm4,thrust[N]\n";
  for (int i = 0; i < 80; ++i) {
    const double p = pwm(rng), v = vbat(rng);
    const double w = tr.omegaSs(p / 65535.0 * v);
    out << p << ',' << v;
    for (int r = 0; r < 4; ++r) out << ',' << std::round(w * kRpm);
    out << ',' << 4.0 * tr.k_f * w * w + scale_noise(rng) << '\n';
  }
}

// A flight: 4 s of hover, 3 s of PWM steps (the vehicle climbing and sinking), 10 s coasting
// level at speed (rotor drag). Only the forces matter to the fits: the attitude stays level.
void writeFlightLog(const Truth& tr, const std::filesystem::path& file) {
  QuadrotorParams p;
  p.thrust_coefficient = tr.k_f;
  p.min_rotor_speed = 0.0;
  p.max_rotor_speed = 5000.0;
  p.time_constant_up = tr.tau_up;
  p.time_constant_down = tr.tau_down;
  p.motor_delay = tr.delay;
  p.rotor_drag_coefficient = tr.drag;
  p.rotor_xy = QuadrotorParams::xLayout(0.05);
  RotorModel rotors(p);
  ImuSettings imu;
  imu.present = true;
  imu.rate = 1.0 / kLogPeriod;
  imu.noise.gyro_noise = tr.gyro_noise;
  imu.noise.accel_noise = tr.accel_noise;
  imu.noise.gyro_bias_walk = imu.noise.accel_bias_walk = 0.0;
  imu.gyro_bias_init = imu.accel_bias_init = 0.0;
  ImuSensor sensor(imu, 11);
  const double w_hover = std::sqrt(tr.mass * tr.g / (4.0 * tr.k_f));
  rotors.reset(Eigen::Vector4d::Constant(w_hover));
  Eigen::Vector3d v = Eigen::Vector3d::Zero();
  std::ofstream out(file);
  out.precision(10);
  out << "t,vbat,pwm1,pwm2,pwm3,pwm4,rpm1,rpm2,rpm3,rpm4,gyro_x,gyro_y,gyro_z,acc_x,acc_y,acc_z,"
         "vx,vy,vz,qw,qx,qy,qz\n";
  const int steps = static_cast<int>(17.0 / kLogPeriod);
  for (int k = 0; k < steps; ++k) {
    const double t = k * kLogPeriod;
    const double vbat = 3.95 - 0.02 * t;  // the battery sags
    Eigen::Vector4d pwm;
    for (int r = 0; r < 4; ++r) {
      double w_cmd = w_hover;
      if (t >= 4.0 && t < 7.0) {
        // Steps of +-25 % every 0.15 s, each rotor on its own phase.
        const int phase = static_cast<int>((t - 4.0 + 0.04 * r) / 0.15);
        w_cmd = w_hover * (phase % 2 == 0 ? 1.25 : 0.75);
      }
      pwm[r] = tr.voltageFor(w_cmd) / vbat * 65535.0;
    }
    if (t >= 7.0 && t < 7.0 + 0.5 * kLogPeriod) v = Eigen::Vector3d(2.5, -1.8, v.z());
    Eigen::Vector4d command;
    for (int r = 0; r < 4; ++r) command[r] = tr.omegaSs(pwm[r] / 65535.0 * vbat);
    rotors.command(command);
    // The forces at this sample: thrust along z, the rotors' drag (sim/rotor_aerodynamics.h).
    AirframeMotion motion;
    motion.R = Eigen::Matrix3d::Identity();
    motion.velocity = v;
    motion.wind = Eigen::Vector3d::Zero();
    motion.angular_velocity = Eigen::Vector3d::Zero();
    const Eigen::Vector4d w = rotors.speeds();
    const Wrench drag = rotorDragWrenchBody(p, motion, w);
    const Eigen::Vector3d force = drag.force + Eigen::Vector3d(0, 0, rotors.thrusts().sum());
    const Eigen::Vector3d specific = force / tr.mass;
    const ImuMeasurement m = sensor.sample(t, Eigen::Vector3d::Zero(), specific);
    out << t << ',' << vbat;
    for (int r = 0; r < 4; ++r) out << ',' << pwm[r];
    for (int r = 0; r < 4; ++r) out << ',' << std::round(w[r] * kRpm);
    out << ',' << m.gyro.x() << ',' << m.gyro.y() << ',' << m.gyro.z() << ',' << m.accel.x() << ','
        << m.accel.y() << ',' << m.accel.z() << ',' << v.x() << ',' << v.y() << ',' << v.z()
        << ",1,0,0,0\n";
    // Two physics steps of 1 ms per log sample, the command held.
    for (int s = 0; s < 2; ++s) {
      rotors.advance(0.5 * kLogPeriod);
      v += 0.5 * kLogPeriod * (specific - Eigen::Vector3d(0, 0, tr.g));
    }
  }
}

double relativeError(double estimate, double truth) {
  return std::abs(estimate - truth) / std::abs(truth);
}

}  // namespace

TEST(IdentifyRoundTrip, RecoversTheParametersTheSimulatorsModelsWroteTheLogsWith) {
  const Truth tr;
  const auto dir = test::makeFreshDir("identify_roundtrip");
  writeStandLog(tr, dir / "stand.csv");
  writeFlightLog(tr, dir / "flight.csv");
  const std::vector<IdentificationLog> logs{readIdentificationLog((dir / "stand.csv").string()),
                                            readIdentificationLog((dir / "flight.csv").string())};
  // The flight's PWM holds three levels only: the map comes from the stand's spread (its own
  // first-order ARX fit on flights is for logs that sweep the voltage, as real flights do).
  IdentifyOptions options;
  options.motor_map_logs = IdentifyOptions::MotorMapLogs::Stand;
  const IdentificationResult r = identify(logs, options);
  ASSERT_TRUE(r.thrust_coefficient.identified);
  ASSERT_TRUE(r.mass.identified) << r.mass.not_why;
  ASSERT_TRUE(r.motor_delay.identified) << r.motor_delay.not_why;
  ASSERT_TRUE(r.time_constant_up.identified) << r.time_constant_up.not_why;
  ASSERT_TRUE(r.time_constant_down.identified) << r.time_constant_down.not_why;
  ASSERT_TRUE(r.rotor_drag.identified) << r.rotor_drag.not_why;
  ASSERT_TRUE(r.gyro_noise.identified) << r.gyro_noise.not_why;
  ASSERT_TRUE(r.accel_noise.identified) << r.accel_noise.not_why;
  EXPECT_LT(relativeError(r.thrust_coefficient.value, tr.k_f), 0.02) << r.thrust_coefficient.value;
  EXPECT_LT(relativeError(r.mass.value, tr.mass), 0.02) << r.mass.value;
  EXPECT_LT(relativeError(r.time_constant_up.value, tr.tau_up), 0.10) << r.time_constant_up.value;
  EXPECT_LT(relativeError(r.time_constant_down.value, tr.tau_down), 0.10)
      << r.time_constant_down.value;
  EXPECT_LT(relativeError(r.motor_delay.value, tr.delay), 0.10) << r.motor_delay.value;
  EXPECT_LT(relativeError(r.rotor_drag.value, tr.drag), 0.10) << r.rotor_drag.value;
  EXPECT_LT(relativeError(r.gyro_noise.value, tr.gyro_noise), 0.10) << r.gyro_noise.value;
  EXPECT_LT(relativeError(r.accel_noise.value, tr.accel_noise), 0.10) << r.accel_noise.value;
  // The motor map's voltage slope, from the stand's rows.
  EXPECT_LT(relativeError(r.motor_speed[1].value, tr.c1), 0.05) << r.motor_speed[1].value;
  // Each interval holds its estimate and the truth of the exactly-modelled fits.
  for (const IdentifiedValue* v : {&r.thrust_coefficient, &r.mass, &r.rotor_drag}) {
    EXPECT_LT(v->ci_low, v->value);
    EXPECT_GT(v->ci_high, v->value);
  }
  EXPECT_LT(r.thrust_coefficient.ci_low, tr.k_f);
  EXPECT_GT(r.thrust_coefficient.ci_high, tr.k_f);

  // What it writes is an airframe file a scenario reads back.
  const auto yaml = dir / "identified.yaml";
  { std::ofstream(yaml) << identificationYaml(r, options); }
  const AirframeFile a = readAirframeFile(yaml);
  ASSERT_TRUE(a.mass && a.thrust_coefficient && a.motor_delay && a.rotor_drag_coefficient &&
              a.gyro_noise && a.motor_speed_coefficients);
  EXPECT_NEAR(*a.mass, r.mass.value, 1e-6 * r.mass.value);
  EXPECT_NEAR((*a.motor_speed_coefficients)[1], r.motor_speed[1].value,
              1e-5 * std::abs(r.motor_speed[1].value));
}
