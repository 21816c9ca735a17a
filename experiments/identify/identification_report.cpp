#include "experiments/identify/identification_report.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "core/atomic_file.h"
#include "core/input_error.h"
#include "render/gnuplot.h"
#include "render/overlay_palette.h"

namespace cosim {

namespace {

constexpr const char* kMarkdownHeader = "<!-- cosim identify: report -->";
constexpr std::size_t kMaxPlotRows = 2500;

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

std::string firstLine(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::string line;
  std::getline(in, line);
  return line;
}

// Refuses to replace `p` unless its first line starts with `header` (cosim identify wrote it).
void checkOurs(const std::filesystem::path& p, const std::string& header) {
  std::error_code ec;
  if (!std::filesystem::exists(p, ec)) return;
  if (const std::string kind = specialFileKind(p); !kind.empty())
    throw InputError(p.string(), "--out", notRegularProblem(kind));
  if (firstLine(p).rfind(header, 0) != 0)
    throw InputError(p.string(), "--out",
                     "exists and was not written by cosim identify; remove it or choose another "
                     "--out");
}

std::filesystem::path sibling(const std::filesystem::path& yaml, const std::string& suffix) {
  return yaml.parent_path() / (yaml.stem().string() + suffix);
}

void yamlValue(std::ostringstream& y, const char* key, const IdentifiedValue& v) {
  if (!v.identified) {
    y << "# " << key << ": not identified (" << v.not_why << ")\n";
    return;
  }
  y << key << ": {value: " << num(v.value) << ", ci95: [" << num(v.ci_low) << ", " << num(v.ci_high)
    << "], residual: " << num(v.residual) << ", residual_unit: \"" << v.residual_unit
    << "\", unit: \"" << v.unit << "\", samples: " << v.samples << "}\n";
}

void markdownRow(std::ostringstream& m, const std::string& name, const IdentifiedValue& v) {
  if (!v.identified) {
    m << "| " << name << " | not identified | | | | " << v.not_why << " |\n";
    return;
  }
  m << "| " << name << " | " << num(v.value) << " " << v.unit << " | [" << num(v.ci_low) << ", "
    << num(v.ci_high) << "] | " << num(v.residual) << " " << v.residual_unit << " | " << v.samples
    << " | " << v.method << " |\n";
}

void writeFigure(const FitFigure& f, const std::filesystem::path& yaml) {
  const std::filesystem::path base = sibling(yaml, "." + f.name);
  const GnuplotScratch scratch(base, f.name);
  std::ostringstream rows;
  const std::size_t n = f.x.size(), step = std::max<std::size_t>(1, n / kMaxPlotRows);
  for (std::size_t k = 0; k < n; k += step)
    rows << num(f.x[k]) << ' ' << num(f.measured[k]) << ' ' << num(f.fitted[k]) << '\n';
  scratch.write("fit.dat", rows.str());
  // A scatter for the maps, lines for the time series.
  const bool series = f.xlabel == "time (s)";
  const std::string measured = hexColour(vehicleColour(0)), fitted = hexColour(vehicleColour(1));
  std::ostringstream b;
  b << "set encoding utf8\nset border lw 1 lc rgb '#404040'\nset grid lc rgb '#dddddd'\n"
    << "set tics out nomirror\nset key top left box lc rgb '#bbbbbb' font ',10'\n"
    << "set title " << gnuplotString(f.title) << "\nset xlabel " << gnuplotString(f.xlabel)
    << "\nset ylabel " << gnuplotString(f.ylabel) << "\n"
    << "plot 'fit.dat' using 1:2 with " << (series ? "lines lw 1.5" : "points pt 7 ps 0.3")
    << " lc rgb '" << measured << "' title 'measured', \\\n"
    << "     'fit.dat' using 1:3 with " << (series ? "lines lw 2.5" : "points pt 7 ps 0.3")
    << " lc rgb '" << fitted << "' title 'identified model'\n";
  runGnuplot(plotBoth(f.name, 900, 600, b.str()), scratch.dir());
  scratch.publish(f.name);
}

}  // namespace

void checkIdentificationOutput(const std::filesystem::path& yaml_path) {
  if (yaml_path.extension() != ".yaml")
    throw InputError(yaml_path.string(), "--out", "the output must be a .yaml file");
  checkOurs(yaml_path, kIdentifiedYamlHeader);
  checkOurs(sibling(yaml_path, ".md"), kMarkdownHeader);
  // The figures carry no mark of their own: they are ours to replace only beside our FILE.yaml.
  std::error_code ec;
  if (std::filesystem::exists(yaml_path, ec)) return;
  for (const char* fit : {"motor_map", "thrust", "motor_lag", "mass", "rotor_drag", "imu_noise",
                          "attitude_roll", "attitude_pitch"})
    for (const char* ext : {".png", ".svg"})
      if (const auto fig = sibling(yaml_path, std::string(".") + fit + ext);
          std::filesystem::exists(fig, ec))
        throw InputError(fig.string(), "--out",
                         "exists beside no FILE.yaml of cosim identify's; remove it or choose "
                         "another --out");
}

std::string identificationYaml(const IdentificationResult& r, const IdentifyOptions& o) {
  std::ostringstream y;
  y << kIdentifiedYamlHeader << " (docs/identify.md), for vehicles[i].airframe.\n"
    << "# Each value: the estimate, its 95 % confidence interval, the RMS residual of its fit\n"
    << "# and the samples used. Logs:\n";
  for (const auto& l : r.logs) y << "#   " << l << "\n";
  if (o.payload_mass > 0.0)
    y << "# A cable-suspended payload of " << num(o.payload_mass)
      << " kg was taken off (its pull on the vehicle).\n";
  yamlValue(y, "mass", r.mass);
  yamlValue(y, "thrust_coefficient", r.thrust_coefficient);
  if (r.motor_speed[0].identified) {
    const auto& c = r.motor_speed;
    y << "# omega_ss = c0 + c1 v + c2 v^2 (rad/s), v = PWM / 65535 * V_battery (V)\n"
      << "motor_speed_coefficients: {value: [" << num(c[0].value) << ", " << num(c[1].value) << ", "
      << num(c[2].value) << "], ci95: [[" << num(c[0].ci_low) << ", " << num(c[0].ci_high) << "], ["
      << num(c[1].ci_low) << ", " << num(c[1].ci_high) << "], [" << num(c[2].ci_low) << ", "
      << num(c[2].ci_high) << "]], residual: " << num(c[0].residual)
      << ", residual_unit: \"rad/s\", unit: \"rad/s, rad/s/V, rad/s/V^2\", samples: "
      << c[0].samples << "}\n";
  } else {
    y << "# motor_speed_coefficients: not identified (" << r.motor_speed[0].not_why << ")\n";
  }
  yamlValue(y, "motor_delay", r.motor_delay);
  yamlValue(y, "time_constant_up", r.time_constant_up);
  yamlValue(y, "time_constant_down", r.time_constant_down);
  yamlValue(y, "rotor_drag_coefficient", r.rotor_drag);
  yamlValue(y, "gyro_noise", r.gyro_noise);
  yamlValue(y, "accel_noise", r.accel_noise);
  const auto tracking = [&](const char* axis, const AttitudeTracking& a) {
    if (!a.gain.identified) return;
    y << "# attitude tracking (not an airframe parameter): " << axis << " = " << num(a.gain.value)
      << " [" << num(a.gain.ci_low) << ", " << num(a.gain.ci_high) << "] x commanded, "
      << num(a.lag.value * 1e3) << " ms [" << num(a.lag.ci_low * 1e3) << ", "
      << num(a.lag.ci_high * 1e3) << "] late\n";
  };
  tracking("roll", r.roll);
  tracking("pitch", r.pitch);
  return y.str();
}

void writeIdentification(const std::filesystem::path& yaml_path, const IdentificationResult& r,
                         const IdentifyOptions& o) {
  checkIdentificationOutput(yaml_path);
  for (const auto& f : r.figures) writeFigure(f, yaml_path);
  std::ostringstream m;
  m << kMarkdownHeader << "\n# Identified airframe parameters\n\nWritten by `cosim identify` "
    << "(docs/identify.md) from:\n\n";
  for (const auto& l : r.logs) m << "- `" << l << "`\n";
  m << "\n| parameter | value | 95 % interval | RMS residual | samples | method or why not |\n"
    << "|---|---|---|---|---|---|\n";
  const char* c_names[3] = {"motor speed c0", "motor speed c1", "motor speed c2"};
  for (int i = 0; i < 3; ++i) markdownRow(m, c_names[i], r.motor_speed[i]);
  markdownRow(m, "thrust constant k_f", r.thrust_coefficient);
  markdownRow(m, "motor delay", r.motor_delay);
  markdownRow(m, "motor time constant up", r.time_constant_up);
  markdownRow(m, "motor time constant down", r.time_constant_down);
  markdownRow(m, "mass", r.mass);
  markdownRow(m, "rotor drag coefficient", r.rotor_drag);
  markdownRow(m, "gyroscope noise density", r.gyro_noise);
  markdownRow(m, "accelerometer noise density", r.accel_noise);
  markdownRow(m, "roll tracking gain", r.roll.gain);
  markdownRow(m, "roll tracking lag", r.roll.lag);
  markdownRow(m, "pitch tracking gain", r.pitch.gain);
  markdownRow(m, "pitch tracking lag", r.pitch.lag);
  m << "\nIntervals: least-squares covariance with the residuals' lag-1 autocorrelation "
       "(effective samples n (1 - rho) / (1 + rho)); delays and lags by profile likelihood over "
       "whole samples.\n\n## Figures\n\n";
  const std::string stem = yaml_path.stem().string();
  for (const auto& f : r.figures)
    m << "### " << f.title << "\n\n![" << f.title << "](" << stem << "." << f.name << ".png)\n\n";
  writeFileAtomically(sibling(yaml_path, ".md"), m.str());
  writeFileAtomically(yaml_path, identificationYaml(r, o));
}

}  // namespace cosim
