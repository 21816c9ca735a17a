#include "run/record/run_record.h"

#include <filesystem>

namespace cosim {

std::string pathSourceName(const Scenario& scenario, const std::string& planner_name) {
  if (!planner_name.empty()) return planner_name;
  std::size_t references = 0;
  const VehicleSpec* flier = nullptr;
  for (const VehicleSpec& v : scenario.vehicles)
    if (v.reference) {
      ++references;
      flier = &v;
    }
  if (references == 0) return "given waypoints";
  if (references < scenario.vehicles.size()) return "given waypoints and references";
  if (references > 1) return "given references";
  return "given reference " + flier->reference_file.filename().string();
}

std::string vehicleControllers(const RunRecord& record) {
  const RunSetup& s = record.setup;
  const std::string& robots = s.robot_sections.controller.name;
  const std::string& quadrotors = s.quadrotor_sections.controller.name;
  if (s.robots.empty()) return quadrotors + " controller";
  if (s.quadrotors.empty() || robots == quadrotors) return robots + " controller";
  return "robots: " + robots + " controller, quadrotors: " + quadrotors + " controller";
}

std::string runTitle(const Scenario& scenario, const RunRecord& record) {
  const MotionSections& primary = record.setup.primarySections();
  const std::string planner = pathSourceName(scenario, primary.planner.name);
  return "cosim run: " + std::filesystem::path(scenario.file).stem().string() + " (" + planner +
         ", " + vehicleControllers(record) + ")";
}

std::string runStatusLine(const RunRecord& record) {
  return record.message.empty() ? "Every vehicle reached its goal without a collision."
                                : "The run failed its task: " + record.message;
}

}  // namespace cosim
