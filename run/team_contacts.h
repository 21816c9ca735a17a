#pragma once
// A run's contacts by kind and its vehicles' closest approaches, from the log: each touching pair
// of vehicles counted once (both book it, sim/contact_monitor.h), contacts with static and with
// moving obstacles, and the smallest surface-to-surface distances between ground robots'
// footprints and between a robot and a moving obstacle (quadrotors fly over them).
#include <vector>

#include "run/record/run_metrics.h"
#include "sim/run_log.h"
#include "sim/vehicle_kind.h"

namespace cosim {

// `kinds[v]`: what log.vehicles[v] is. Vehicles and obstacles must be logged at the same instants.
TeamContacts teamContacts(const RunLog& log, const std::vector<VehicleKind>& kinds);

}  // namespace cosim
