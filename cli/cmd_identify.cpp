// cosim identify LOG... [--out FILE.yaml]: system identification of a quadrotor from Crazyflie
// uSD logs and CSV logs with named columns (experiments/identify/). Writes FILE.yaml (airframe
// parameters for a scenario's vehicles[i].airframe), FILE.md and a figure per fit.
#include <cstdio>
#include <filesystem>

#include "cli/command.h"
#include "cli/option_checks.h"
#include "core/output_manifest.h"
#include "experiments/identify/identification_report.h"

namespace cosim::cli {

namespace {

struct IdentifyArgs {
  std::vector<std::string> logs;
  std::string out = "identified_airframe.yaml";
  IdentifyOptions options;
  std::string motor_map_from = "auto";
};

void printValue(const char* name, const IdentifiedValue& v) {
  if (!v.identified) {
    std::printf("%-26s not identified: %s\n", name, v.not_why.c_str());
    return;
  }
  std::printf("%-26s %.6g %s  95%% [%.6g, %.6g]  residual %.4g %s  (%zu samples)\n", name, v.value,
              v.unit.c_str(), v.ci_low, v.ci_high, v.residual, v.residual_unit.c_str(), v.samples);
}

void runIdentify(const IdentifyArgs& a) {
  checkIdentificationOutput(a.out);
  std::vector<IdentificationLog> logs;
  for (const auto& path : a.logs) logs.push_back(readIdentificationLog(path));
  const IdentificationResult r = identify(logs, a.options);
  printValue("motor speed c0", r.motor_speed[0]);
  printValue("motor speed c1", r.motor_speed[1]);
  printValue("motor speed c2", r.motor_speed[2]);
  printValue("thrust constant k_f", r.thrust_coefficient);
  printValue("motor delay", r.motor_delay);
  printValue("time constant up", r.time_constant_up);
  printValue("time constant down", r.time_constant_down);
  printValue("mass", r.mass);
  printValue("rotor drag coefficient", r.rotor_drag);
  printValue("gyro noise density", r.gyro_noise);
  printValue("accel noise density", r.accel_noise);
  printValue("roll tracking gain", r.roll.gain);
  printValue("roll tracking lag", r.roll.lag);
  printValue("pitch tracking gain", r.pitch.gain);
  printValue("pitch tracking lag", r.pitch.lag);
  // What it writes joins the manifest of FILE.yaml's folder, last: a later identify into the
  // same place may replace it (core/output_manifest.h).
  const std::filesystem::path out(a.out);
  OutputManifestScope manifest(out.has_parent_path() ? out.parent_path() : ".", "identify");
  writeIdentification(a.out, r, a.options);
  manifest.finish();
  std::printf("written: %s, its .md report and %zu figures\n", a.out.c_str(), r.figures.size());
}

}  // namespace

void addIdentifyCommand(CLI::App& app, CommandContext& ctx) {
  auto* cmd = app.add_subcommand(
      "identify",
      "System identification of a quadrotor from its logs: Crazyflie uSD-card binary logs\n"
      "and CSV files whose header names the columns (t, vbat, pwm or pwm1..4, rpm1..4,\n"
      "thrust, gyro_x.., acc_x.., vx, vy, vz, qw.., payload_vx.., roll, roll_des, ...; a unit\n"
      "in brackets, e.g. thrust[g]). Identifies what the logs allow: the motor map\n"
      "omega_ss = c0 + c1 v + c2 v^2 (v = PWM/65535 V_battery), the thrust constant k_f\n"
      "(thrust = k_f omega^2, from a thrust stand), the motor delay and time constants, the\n"
      "mass from hover thrust, the rotor drag coefficient, the IMU noise densities in hover,\n"
      "and how the attitude follows its command. Each value with its 95 % interval and\n"
      "residual in FILE.yaml (usable as a scenario's vehicles[i].airframe), a report FILE.md\n"
      "and a figure per fit. See docs/identify.md.");
  auto a = std::make_shared<IdentifyArgs>();
  cmd->add_option("logs", a->logs, "logs: Crazyflie uSD binary or CSV with named columns")
      ->required();
  cmd->add_option("--out", a->out,
                  "the identified airframe, a .yaml file (default "
                  "identified_airframe.yaml); FILE.md and figures beside it");
  cmd->add_option("--payload-mass", a->options.payload_mass,
                  "kg of a cable-suspended payload: its pull is taken off the hover thrust and "
                  "the specific force (default 0: none)")
      ->check(numberIn(0.0, 100.0));
  cmd->add_option("--thrust-coefficient", a->options.thrust_coefficient,
                  "k_f in N/(rad/s)^2 to use instead of a thrust stand log (for the mass)")
      ->check(numberIn(1e-12, 1.0));
  cmd->add_option("--mass", a->options.mass,
                  "kg, to use instead of the hover mass (for the rotor drag)")
      ->check(numberIn(1e-4, 1e4));
  cmd->add_option("--hover-speed", a->options.hover_speed,
                  "m/s below which the vehicle hovers (default 0.1)")
      ->check(numberIn(1e-3, 10.0));
  cmd->add_option("--min-hover", a->options.min_hover_s,
                  "s: the shortest hover segment used (default 1)")
      ->check(numberIn(0.2, 1e4));
  cmd->add_option("--motor-map-from", a->motor_map_from,
                  "the logs the motor map is fitted on: auto (default: the flights if any, else "
                  "the stand), flight (timed logs) or stand (logs without time)")
      ->check(CLI::IsMember({"auto", "flight", "stand"}));
  cmd->add_option("--max-motor-delay", a->options.max_motor_delay,
                  "s: the longest motor delay searched (default 0.06)")
      ->check(numberIn(0.0, 1.0));
  cmd->callback([a, &ctx] {
    using Logs = IdentifyOptions::MotorMapLogs;
    a->options.motor_map_logs = a->motor_map_from == "flight"  ? Logs::Flight
                                : a->motor_map_from == "stand" ? Logs::Stand
                                                               : Logs::Auto;
    runIdentify(*a);
    ctx.status = 0;
  });
}

}  // namespace cosim::cli
