#include "run/record/run_record.h"

#include <filesystem>

namespace cosim {

std::string runTitle(const Scenario& scenario, const RunRecord& record) {
  const MotionSections& primary = record.setup.primarySections();
  const std::string planner =
      primary.planner.name.empty() ? "given waypoints" : primary.planner.name;
  return "cosim run: " + std::filesystem::path(scenario.file).stem().string() + " (" + planner +
         ", " + primary.controller.name + " controller)";
}

std::string runStatusLine(const RunRecord& record) {
  return record.message.empty() ? "Every vehicle reached its goal without a collision."
                                : "The run failed its task: " + record.message;
}

}  // namespace cosim
