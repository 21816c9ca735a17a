// Reading a scenario's `sim:` section (part of sim/scenario_loader.cpp): the physics timestep,
// the control rate, the run's length, the seed and the goal tolerance, and the limits they set
// on the rest of the scenario.
#include <cmath>
#include <cstdint>
#include <string>

#include "control/crazyflie_control_rate.h"
#include "sim/declared_key_reader.h"
#include "sim/scenario_reference.h"
#include "sim/scenario_sections.h"

namespace cosim {

namespace {

// The flight log keeps one sample (368 bytes) per vehicle per control step, as the flight goes
// (sim/log_growth.h): 20 million samples, a run that flies its whole max_time, is about 7 GB.
// More is a mistake (a day at 10 kHz), refused before anything is allocated.
constexpr double kMaxLogSamples = 2e7;

}  // namespace

void readSimSection(const YamlReader& r, const YAML::Node& root, Scenario& s) {
  if (root["sim"]) {
    const YAML::Node n = root["sim"];
    readDeclaredKeys(r, n, "sim", s.sim);
    const double ratio = 1.0 / (s.sim.timestep * s.sim.control_rate);
    if (ratio < 1.0 - 1e-9 || std::abs(ratio - std::round(ratio)) > 1e-6)
      r.fail(n["control_rate"] ? n["control_rate"] : n, "sim.control_rate",
             "the physics rate (1/timestep) must be a whole multiple of the control rate");
  }
  for (const std::string& name : {s.motion.controller.name, s.aerial.controller.name})
    if (const std::string why = crazyflieControlRateProblem(name, s.sim.control_rate); !why.empty())
      r.fail(root["sim"] && root["sim"]["control_rate"] ? root["sim"]["control_rate"] : root,
             "sim.control_rate", why);
  if (const double samples =
          s.sim.max_time * s.sim.control_rate * static_cast<double>(s.vehicles.size());
      samples > kMaxLogSamples)
    r.fail(
        root["sim"] ? root["sim"] : root, "sim.max_time",
        "max_time x control_rate x vehicles = " + std::to_string(static_cast<long long>(samples)) +
            " log samples, more than 20 million: shorten sim.max_time or lower sim.control_rate");
  checkReferenceStarts(r, root, s);
}

}  // namespace cosim
