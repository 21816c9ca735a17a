#include "run/team_tracking_margin.h"

#include <algorithm>

#include "control/controller_registry.h"

namespace cosim {

namespace {

// Reserve over the measured shortfall (see the header).
constexpr double kReserve = 1.25;

}  // namespace

double teamPairDeviation(const std::string& controller) {
  // Each controller's shortfall is declared with it (ControllerEntry::team_shortfall, with the
  // flown closest approaches it comes from).
  const ControllerRegistry& registry = ControllerRegistry::instance();
  if (const ControllerEntry* entry = registry.find(controller)) return entry->team_shortfall;
  double largest = 0.0;
  for (const ControllerEntry& e : registry.entries()) largest = std::max(largest, e.team_shortfall);
  return largest;
}

double teamSeparationFor(const std::string& controller, double min_separation) {
  return std::max(min_separation, 1.0 + kReserve * teamPairDeviation(controller));
}

}  // namespace cosim
