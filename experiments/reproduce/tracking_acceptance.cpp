// The tracking acceptance table: every bundled 3D world flown with the 1.5 kg quadrotor at up to
// 3 m/s and with the Crazyflie-class nano-quad at up to 1 m/s, minimum-snap trajectories under
// the geometric controller (rotor-drag compensation where the world has rotor drag), flying on the
// EKF's estimate from motion-capture sensing. Targets: zero collisions everywhere; RMSE <= 5 cm and
// max error
// <= 15 cm for quad_1500g; RMSE <= 2 cm for cf2.
#include <algorithm>
#include <filesystem>
#include <sstream>

#include "core/input_error.h"
#include "experiments/reproduce/report_files.h"
#include "experiments/reproduce/reproduction.h"
#include "run/run_pipeline.h"

namespace cosim::reproduce {

namespace {

// The bundled scenarios flown by a single quadrotor (ground-robot scenarios are left out).
std::vector<std::filesystem::path> quadrotorScenarios() {
  std::vector<std::filesystem::path> out;
  for (const auto& e : std::filesystem::directory_iterator(COSIM_SCENARIOS_DIR)) {
    if (e.path().extension() != ".yaml") continue;
    try {
      const Scenario s = loadScenario(e.path().string());
      if (s.vehicles.size() == 1 && s.vehicles[0].kind == VehicleKind::Quadrotor &&
          s.moving_obstacles.empty())
        out.push_back(e.path());
    } catch (const InputError&) {
      // Not a single-quadrotor scenario this table can fly.
    }
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace

Report trackingAcceptance(const Options& options) {
  struct Airframe {
    const char* model;
    double max_speed, max_rmse, max_error;
  };
  const Airframe airframes[] = {{"quad_1500g", 3.0, 0.05, 0.15}, {"cf2", 1.0, 0.02, 0.15}};
  std::ostringstream md;
  md << "# Tracking on every bundled 3D world\n\n"
     << "Planner and disturbances as in each scenario file, minimum-snap trajectory (speed limit "
        "below, acceleration 3 m/s^2), geometric controller (with rotor-drag compensation where "
        "the world has rotor drag), "
        "motion-capture sensing (1 mm, 0.5 deg, 100 Hz, 10 ms late, ADIS16448-class IMU) fused by "
        "the error-state EKF (the controller sees only the estimate), MuJoCo at 1 kHz, control "
        "500 Hz, seed "
     << options.seed
     << ". Targets: 0 collisions; quad_1500g RMSE <= 0.05 m and max error <= "
        "0.15 m; cf2 RMSE <= 0.02 m.\n\n"
     << "| world | vehicle | max speed [m/s] | reached | collisions | RMSE [m] | max error [m] | "
        "min clearance [m] | flight [s] | target |\n|---|---|---|---|---|---|---|---|---|---|\n";
  std::vector<JsonObject> rows;
  int failures = 0, index = 0;
  for (const auto& file : quadrotorScenarios()) {
    for (const Airframe& a : airframes) {
      std::vector<std::string> overrides = {
          "trajectory={mode: minimum_snap, max_speed: " + fixed(a.max_speed, 1) +
              ", max_acceleration: 3.0}",
          "controller={name: geometric}", "sensors={preset: mocap}", "estimator={name: ekf}",
          "sim.seed=" + std::to_string(options.seed)};
      if (options.quick) overrides.push_back("sim.max_time=15");
      Scenario s = loadScenario(file.string(), overrides);
      // Compensate rotor drag where the world has it (compensating drag that is not there
      // would itself be a model error).
      s.motion.controller.drag_compensation = s.disturbances.rotor_drag;
      // Swap the airframe in (the vehicle entry is a list item, which --set cannot address).
      s.vehicles[0].model = a.model;
      s.vehicles[0].model_file = modelsDirectory() / (std::string(a.model) + ".xml");
      s.sim.max_time = std::max(s.sim.max_time, options.quick ? 15.0 : 400.0);
      RunRequest request;
      request.out_dir = std::filesystem::path(options.out_dir) /
                        (std::to_string(index++) + "-" + file.stem().string() + "-" + a.model);
      std::filesystem::create_directories(request.out_dir);
      request.video = false;
      request.images = false;
      const RunRecord r = executeRun(s, request);
      const FlightMetrics& m = r.metrics.vehicles.front();
      const bool ok = m.reached_goal && m.collisions == 0 && m.rmse_m <= a.max_rmse &&
                      m.max_error_m <= a.max_error;
      failures += ok ? 0 : 1;
      md << "| " << file.stem().string() << " | " << a.model << " | " << fixed(a.max_speed, 1)
         << " | " << (m.reached_goal ? "yes" : "no") << " | " << m.collisions << " | "
         << fixed(m.rmse_m, 4) << " | " << fixed(m.max_error_m, 4) << " | "
         << fixed(m.min_clearance_m, 3) << " | " << fixed(m.flight_time_s, 1) << " | "
         << (ok ? "met" : "NOT met") << " |\n";
      JsonObject row;
      row.add("world", file.stem().string())
          .add("vehicle", a.model)
          .add("max_speed_mps", a.max_speed)
          .add("reached_goal", m.reached_goal)
          .add("collisions", m.collisions)
          .add("rmse_m", m.rmse_m)
          .add("max_error_m", m.max_error_m)
          .add("min_clearance_m", m.min_clearance_m)
          .add("flight_time_s", m.flight_time_s)
          .add("target_met", ok);
      rows.push_back(row);
    }
  }
  md << "\n"
     << (failures == 0 ? "Every row meets its target."
                       : std::to_string(failures) + " row(s) miss their target.")
     << "\n";
  return {md.str(), rows};
}

}  // namespace cosim::reproduce
