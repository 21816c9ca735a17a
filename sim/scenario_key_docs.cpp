#include "sim/scenario_key_docs.h"

#include <vector>

#include "sim/declared_key_docs.h"
#include "sim/scenario.h"
#include "sim/sensors/sensor_presets.h"

namespace cosim {

namespace {

std::string table(const std::string& section, const std::string& note,
                  const std::vector<DeclaredKeyRow>& rows) {
  std::string out = "### `" + section + "`\n\n";
  if (!note.empty()) out += note + "\n\n";
  out += "| key | type | default | range | meaning |\n|---|---|---|---|---|\n";
  for (const DeclaredKeyRow& row : rows)
    out += "| `" + row.name + "` | " + row.type + " | " + row.default_value + " | " + row.range +
           " | " + row.doc + " |\n";
  return out + "\n";
}

}  // namespace

std::string declaredKeysMarkdown() {
  std::string out;
  out += table("sim", "", declaredKeyRows(SimSettings{}));
  out += table("sensors", "Without the section: ideal sensing, the exact state.",
               declaredKeyRows(SensorSettings{}));
  // A block without a preset starts from the motion-capture preset's values for that sensor.
  const SensorSettings mocap = sensorPreset("mocap");
  const std::string from_mocap = "A block's defaults are the `mocap` preset's.";
  out += table("sensors.imu", from_mocap, declaredKeyRows(mocap.imu));
  out += table("sensors.position", from_mocap, declaredKeyRows(mocap.position));
  out += table("sensors.attitude", from_mocap, declaredKeyRows(mocap.attitude));
  out += table("estimator", "", declaredKeyRows(EstimatorSettings{}));
  out += table("team", "A quadrotor team planned jointly (docs/quadrotor_teams.md).",
               declaredKeyRows(TeamSettings{}));
  out += table("disturbances", "All off by default; wind and gusts need a drag term.",
               declaredKeyRows(DisturbanceSettings{}));
  out += table("render", "", declaredKeyRows(RenderSettings{}));
  const std::string aerial = "`aerial.` takes the same keys for the quadrotors over ground robots.";
  out += table("planner", aerial + " Every other key is one of the planner's parameters.",
               declaredKeyRows(PlannerSection{}));
  out += table("trajectory", aerial + " Every other key is one of the mode's parameters.",
               declaredKeyRows(TrajectorySection{}));
  out += table("controller", aerial, declaredKeyRows(ControllerSection{}));
  out += table("world.grid_map", "A MovingAI map as the world: see Grid maps below.",
               declaredKeyRows(GridMapSpec{}));
  out += table("vehicles[i].battery", "crazyflie_* controllers only (docs/crazyflie.md).",
               declaredKeyRows(BatterySettings{}));
  out += table("model_error", "Each factor is belief / truth (1: exact).",
               declaredKeyRows(ModelError{}));
  return out;
}

}  // namespace cosim
