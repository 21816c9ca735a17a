// `cosim reproduce crazyflie-figure8`: a prediction of how a real Crazyflie 2.1 Brushless (37 g,
// crazyflie-firmware's controllers with their default gains, motion capture into the
// firmware's Kalman estimator) tracks Crazyswarm2's figure-eight at timescales 1.0 down to 0.5, and
// what makes the error grow with speed. Every flight is the bundled
// experiments/scenarios/crazyflie_figure8.yaml (what `cosim run` flies) with its timescale and
// controller set; the firmware is configured for the flown mass, as its documentation asks (the
// controllers believe vehicles[0].mass). One more column flies crazyflie_lee with the firmware left
// at its default CF_MASS (39.3 g) on the 37 g vehicle; the effect rows fly crazyflie_lee with one
// effect switched off at a time (experiments/reproduce/crazyflie_figure8_variants.h): sensing, the
// firmware's estimator, mocap latency, IMU noise, the battery's sag, rotor drag, motor lag, the
// rotors' speed limit. RMSE and max error as `cosim run` reports them: the true position against
// the reference over the reference's duration. Beside them, how the flight follows the reference
// from its true start (t = 0): its lag and amplitude ratio per axis
// (experiments/compare/axis_tracking.h, as compare-real reports them), and its RMSE when the start
// is fitted instead (the reference shifted in time by least squares,
// experiments/compare/reference_alignment.h): the part of the error that is lag alone.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <sstream>

#include "control/crazyflie_platform.h"
#include "control/piecewise_polynomial_reference.h"
#include "core/atomic_file.h"
#include "core/json_writer.h"
#include "experiments/compare/axis_tracking.h"
#include "experiments/compare/reference_alignment.h"
#include "experiments/reproduce/crazyflie_figure8_variants.h"
#include "experiments/reproduce/report_files.h"
#include "experiments/reproduce/reproduction.h"
#include "render/comparison_chart.h"
#include "run/given_reference_flight.h"
#include "run/run_evaluation.h"
#include "sim/flight_metrics.h"
#include "sim/flight_simulation.h"
#include "sim/world_model.h"

namespace cosim::reproduce {

namespace {

struct Figure8Row {
  std::string controller;
  double timescale = 1.0, peak_speed = 0.0, rmse = 0.0, max_error = 0.0;
  RunEnd end_reason = RunEnd::Running;
  AxisTracking axes;  // against the reference from its true start
  // The best start of the reference (s after the true one, >= 0: the flight begins at t = 0) and
  // the RMSE there; NaN if the flight ended before the reference did.
  double fitted_start = std::numeric_limits<double>::quiet_NaN();
  double rmse_start_fitted = std::numeric_limits<double>::quiet_NaN();
  // The same two RMSEs with the mean offset (flown minus reference) removed: what is left when a
  // constant height or position offset (the battery's charge, the mass the firmware believes)
  // does not count, as a comparison with real flights whose offset differs should count it.
  double rmse_offset_removed = std::numeric_limits<double>::quiet_NaN();
  double rmse_start_fitted_offset_removed = std::numeric_limits<double>::quiet_NaN();
};

// Lag and amplitude per axis, and the RMSE with the reference's start fitted, of `v`'s flight
// over the reference's duration.
void followTheReference(Figure8Row& row, const VehicleLog& v, double reference_end) {
  std::vector<double> t;
  std::vector<Eigen::Vector3d> reference;
  SampledPath flown;
  for (const LogSample& x : v.samples) {
    if (!flown.t.empty() && x.t <= flown.t.back()) continue;
    flown.t.push_back(x.t);
    flown.p.push_back(x.pos);
    if (x.t <= reference_end) {
      t.push_back(x.t);
      reference.push_back(x.ref_pos);
    }
  }
  if (t.size() < kMinWindowLogSamples || flown.size() < 2) return;
  row.axes = axisTracking(t, reference, flown);
  AlignmentProblem start;
  start.s = t;
  start.target = reference;
  start.log = &flown;
  if (searchedOffsets(start).empty()) return;
  const Alignment fitted = fitAlignment(start);
  row.fitted_start = fitted.time_offset;
  row.rmse_start_fitted = fitted.rms;
  // Least squares over a translation too: at the best start, the mean offset removed.
  start.translation = FittedTranslation::XYZ;
  row.rmse_start_fitted_offset_removed = fitAlignment(start).rms;
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (std::size_t k = 0; k < t.size(); ++k) mean += flown.p[k] - reference[k];
  mean /= static_cast<double>(t.size());
  double sum = 0.0;
  for (std::size_t k = 0; k < t.size(); ++k)
    sum += (flown.p[k] - reference[k] - mean).squaredNorm();
  row.rmse_offset_removed = std::sqrt(sum / static_cast<double>(t.size()));
}

Figure8Row fly(const FigureEightVariant& v, double timescale, const Options& options) {
  const Scenario s = figureEightScenario(v, timescale, options.seed);
  const WorldModel world = WorldModel::fromXml(figureEightModelXml(v, s), s);
  FlightOptions flight;
  flight.settings = s.sim;
  const RunLog log = flyGivenReference(s, world, flight);
  const double reference_end = s.vehicles[0].reference->duration();

  Figure8Row row;
  row.controller = v.label;
  row.timescale = timescale;
  row.end_reason = log.end_reason;
  const FlightMetrics m = evaluateReferenceFlight(s, log);
  row.rmse = m.rmse_m;
  row.max_error = m.max_error_m;
  for (const LogSample& x : log.vehicles[0].samples)
    if (x.t <= reference_end) row.peak_speed = std::max(row.peak_speed, x.ref_vel.norm());
  followTheReference(row, log.vehicles[0], reference_end);
  return row;
}

const Figure8Row& find(const std::vector<Figure8Row>& rows, const std::string& label, double ts) {
  for (const Figure8Row& r : rows)
    if (r.controller == label && std::abs(r.timescale - ts) < 1e-9) return r;
  throw std::logic_error("no row " + label);
}

// [x, y, z], null where not a number.
std::string xyzJson(const Eigen::Vector3d& v) {
  std::string s = "[";
  for (int a = 0; a < 3; ++a) {
    if (a) s += ", ";
    s += JsonObject::number(v[a]);
  }
  s += "]";
  return s;
}

std::string orDash(double v, int decimals) {
  return std::isfinite(v) ? fixed(v, decimals) : std::string("-");
}

// How each variant's flight follows the reference from its true start.
std::string followingTable(const std::vector<Figure8Row>& rows, const std::vector<double>& scales,
                           const std::vector<const FigureEightVariant*>& variants) {
  std::ostringstream md;
  md << "\n| timescale | configuration | lag x, y [s] | amplitude x, y | fitted start [s] | "
        "RMSE start fitted / true start [m] | the same, mean offset removed [m] |\n"
        "|---|---|---|---|---|---|---|\n";
  for (double ts : scales)
    for (const FigureEightVariant* c : variants) {
      const Figure8Row& r = find(rows, c->label, ts);
      md << "| " << fixed(ts, 1) << " | " << c->label << " | " << orDash(r.axes.lag_s.x(), 3)
         << ", " << orDash(r.axes.lag_s.y(), 3) << " | " << orDash(r.axes.amplitude_ratio.x(), 3)
         << ", " << orDash(r.axes.amplitude_ratio.y(), 3) << " | " << orDash(r.fitted_start, 3)
         << " | " << orDash(r.rmse_start_fitted, 4) << " / " << fixed(r.rmse, 4) << " | "
         << orDash(r.rmse_start_fitted_offset_removed, 4) << " / "
         << orDash(r.rmse_offset_removed, 4) << " |\n";
    }
  return md.str();
}

constexpr char kFollowingIntro[] =
    "\nHow the flights follow the reference from its true start (t = 0): lag per axis (best time "
    "shift of the flight against the reference, s; positive: late), amplitude ratio per axis "
    "(least-squares gain of the lag-corrected flight on the reference; 1: full size), and the "
    "RMSE with the reference's start fitted (shifted by least squares, by the start shown; never "
    "before t = 0, where the flight begins, so 0 means the flight is not late as a whole) beside "
    "the RMSE against its true start; then both with the mean offset (flown minus reference) "
    "removed, the figures a comparison with real flights whose constant offset differs (the "
    "battery's charge at take-off, the mass the firmware believes) rests on. The figure-eight is "
    "flat: z has neither lag nor amplitude.\n";

std::string markdown(const std::vector<Figure8Row>& rows, const std::vector<double>& scales,
                     const std::vector<const FigureEightVariant*>& controllers,
                     const std::vector<const FigureEightVariant*>& effects,
                     const Options& options) {
  std::ostringstream md;
  md << "# Crazyflie 2.1 Brushless on Crazyswarm2's figure-eight: predicted tracking error\n\n"
     << "experiments/scenarios/crazyflie_figure8.yaml, the rig as flown: cf21_brushless at 37 g "
        "with its identified motors, rotor drag and IMU noise "
        "(models/cf21_brushless_identified.yaml), crazyflie-firmware's controllers with their "
        "default gains and loop rates, IMRCLab's 2024 thrust path (quadratic PWM map, no battery "
        "compensation, cf2 mixer constants) on a 1S battery, motion capture (100 Hz, 1 mm, 11 ms "
        "late) into the firmware's Kalman estimator; figure8.csv relative to the 1 m start, "
        "flown from hover at t = 0. MuJoCo at 1 kHz, control at 500 Hz, seed "
     << options.seed
     << ". RMSE and max error: true position against the reference over the reference's "
        "duration, as `cosim run` reports them.\n\n| timescale | peak speed [m/s] |";
  for (const FigureEightVariant* c : controllers)
    md << " " << c->label << (c->firmware_default_mass ? " (firmware at its default CF_MASS)" : "")
       << " RMSE / max [m] |";
  md << "\n|---|---|";
  for (std::size_t i = 0; i < controllers.size(); ++i) md << "---|";
  md << "\n";
  for (double ts : scales) {
    md << "| " << fixed(ts, 1) << " | "
       << fixed(find(rows, controllers[0]->label, ts).peak_speed, 2) << " |";
    for (const FigureEightVariant* c : controllers) {
      const Figure8Row& r = find(rows, c->label, ts);
      const std::string ended = runEndName(r.end_reason);
      md << " " << fixed(r.rmse, 4) << " / " << fixed(r.max_error, 4)
         << (r.end_reason == RunEnd::Goal ? "" : " (" + ended + ")") << " |";
    }
    md << "\n";
  }
  md << "\nThe firmware's controllers believe the flown 37 g (vehicles[0].mass): "
        "crazyflie-firmware "
        "asks for CF_MASS to be updated to the vehicle's mass (CONFIG_MODIFIED_CF_MASS, "
        "ctrlLee.mass). "
     << kFirmwareDefaultMass
     << " is crazyflie_lee with the firmware left at its default CF_MASS = 39.3 g: with no "
        "position integral (Kpos_I = 0) it holds up 2.3 g more than the vehicle weighs and settles "
        "(1 - 37/39.3) "
        "9.81 / 7 = 8.2 cm high, an offset that dominates the error at low speed.\n";
  md << kFollowingIntro << followingTable(rows, scales, controllers);
  if (effects.empty()) {
    md << "\nFigure: crazyflie-figure8.png (RMSE against peak speed per controller). Rows in "
          "crazyflie-figure8.json.\n";
    if (options.quick)
      md << "\n(--quick: timescales 1.0 and 0.5, crazyflie_lee and " << kFirmwareDefaultMass
         << " only.)\n";
    return md.str();
  }
  md << "\nWhat drives crazyflie_lee's error: the same flights with one effect switched off; "
        "each cell is the RMSE [m] and, in brackets, the share of the full model's RMSE that "
        "goes away without that effect.\n\n| timescale | full model |";
  for (const FigureEightVariant* e : effects) md << " " << e->label << " |";
  md << "\n|---|---|";
  for (std::size_t i = 0; i < effects.size(); ++i) md << "---|";
  md << "\n";
  for (double ts : scales) {
    const double full = find(rows, "crazyflie_lee", ts).rmse;
    md << "| " << fixed(ts, 1) << " | " << fixed(full, 4) << " |";
    for (const FigureEightVariant* e : effects) {
      const double r = find(rows, e->label, ts).rmse;
      md << " " << fixed(r, 4) << " (" << fixed(100.0 * (full - r) / full, 0) << " %) |";
    }
    md << "\n";
  }
  md << "\ncrazyflie_lee with one effect off, how it follows the reference:\n"
     << followingTable(rows, scales, effects);
  md << "\nFigure: crazyflie-figure8.png (RMSE against peak speed per controller). Rows in "
        "crazyflie-figure8.json.\n";
  return md.str();
}

}  // namespace

Report crazyflieFigure8(const Options& options) {
  const std::vector<double> scales = options.quick
                                         ? std::vector<double>{1.0, 0.5}
                                         : std::vector<double>{1.0, 0.9, 0.8, 0.7, 0.6, 0.5};
  std::vector<const FigureEightVariant*> controllers, effects;
  for (const FigureEightVariant& v : kFigureEightControllers)
    if (!options.quick || std::string(v.controller) == "crazyflie_lee") controllers.push_back(&v);
  if (!options.quick)
    for (const FigureEightVariant& v : kFigureEightEffects) effects.push_back(&v);
  std::vector<Figure8Row> rows;
  for (double ts : scales) {
    for (const FigureEightVariant* v : controllers) rows.push_back(fly(*v, ts, options));
    for (const FigureEightVariant* v : effects) rows.push_back(fly(*v, ts, options));
  }

  const std::filesystem::path dir(options.out_dir);
  std::vector<JsonObject> json_rows;
  std::string csv = "controller,timescale,peak_speed_mps,rmse_m,max_error_m\n";
  for (const Figure8Row& r : rows) {
    JsonObject j;
    j.add("controller", r.controller)
        .add("timescale", r.timescale)
        .add("peak_speed_mps", r.peak_speed)
        .add("rmse_m", r.rmse)
        .add("max_error_m", r.max_error)
        .add("end_reason", runEndName(r.end_reason))
        .raw("lag_s", xyzJson(r.axes.lag_s))
        .raw("amplitude_ratio", xyzJson(r.axes.amplitude_ratio))
        .add("fitted_start_s", r.fitted_start)
        .add("rmse_start_fitted_m", r.rmse_start_fitted)
        .add("rmse_offset_removed_m", r.rmse_offset_removed)
        .add("rmse_start_fitted_offset_removed_m", r.rmse_start_fitted_offset_removed);
    json_rows.push_back(j);
    csv += r.controller + "," + fixed(r.timescale, 2) + "," + JsonObject::number(r.peak_speed) +
           "," + JsonObject::number(r.rmse) + "," + JsonObject::number(r.max_error) + "\n";
  }
  writeFileAtomically(dir / "crazyflie-figure8.csv", csv);
  writeComparisonChart(dir / "crazyflie-figure8.csv", "peak_speed_mps", "rmse_m", "controller",
                       dir / "crazyflie-figure8");
  return {markdown(rows, scales, controllers, effects, options), json_rows};
}

}  // namespace cosim::reproduce
