#pragma once
// A log for system identification (cosim identify) as one table of named columns in SI units,
// whichever file it came from. Two formats, told apart by their content (the uSD log's first
// byte is 0xBC; anything else is read as CSV text):
//   a CSV whose header names its columns, each optionally with its unit in brackets
//   ("thrust[g]", "vbat[V]"); unknown columns are ignored (a thrust stand's current, say);
//   a Crazyflie uSD-card binary log (experiments/compare/usd_log_reader.h): the event type with
//   the most of the firmware variables below is read.
// The columns, their CSV units (the first is the default) and uSD variables:
//   t           s, ms, us        the event's time              (absent: a thrust stand's rows)
//   vbat        V, mV            pm.vbatMV, pm.vbat            battery voltage
//   pwm1..pwm4  (0..65535)       pwm.m1_pwm..m4_pwm            a CSV's `pwm` applies to all four
//   omega1..4   rad/s, rpm       rpm.m1..m4 (rpm)              a CSV may call them rpm1..rpm4
//   thrust      N, g             -                             total of the rotors (thrust stand)
//   gyro_x/y/z  rad/s, deg/s     gyro.x/y/z (deg/s)            body rates
//   acc_x/y/z   m/s^2, g         acc.x/y/z (g)                 body specific force
//   vx, vy, vz  m/s              stateEstimate.vx/vy/vz        world velocity (mocap-fused)
//   qw,qx,qy,qz                  stateEstimate.qw/qx/qy/qz     attitude, body to world
//   payload_vx/vy/vz  m/s        stateEstimateZ.pvx/pvy/pvz (mm/s)  a cable-suspended payload
//   roll, pitch, roll_des, pitch_des  rad, deg   ctrlLee.rpyx/rpyy, ctrlLee.rpydx/rpydy
// Bad input is an InputError naming the file and the line or byte: a known column with an
// unknown unit, a column twice, a value that is not a finite number, times that do not increase.
#include <map>
#include <string>
#include <vector>

namespace cosim {

struct IdentificationLog {
  std::string file;
  std::string format;                                  // "csv" or "Crazyflie uSD log version N"
  std::vector<double> t;                               // s; empty for a table without time
  std::map<std::string, std::vector<double>> columns;  // each as long as the rows
  std::size_t rows = 0;

  bool has(const std::string& name) const { return columns.count(name) > 0; }
  bool hasAll(const std::vector<std::string>& names) const;
  const std::vector<double>& column(const std::string& name) const { return columns.at(name); }
  // The median sampling interval, s (0 without time).
  double samplePeriod() const;
};

// Reads `path` (a regular file, at most kMaxLogFileBytes) in whichever format it is.
IdentificationLog readIdentificationLog(const std::string& path);

IdentificationLog parseIdentificationCsv(const std::string& text, const std::string& file);
IdentificationLog parseIdentificationUsd(std::string bytes, const std::string& file);

}  // namespace cosim
