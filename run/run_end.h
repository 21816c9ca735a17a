#pragma once
// What a run's end (RunEnd, sim/run_log.h) means for its outcome: whether it was a fault of the
// simulated vehicles, and how to say so to a person.
#include <string>

#include "sim/run_log.h"

namespace cosim {

// A fault of the simulated vehicles (metrics.json's "fault"): diverged, unstable or saturated.
bool isFault(RunEnd end);

// Why a run whose simulation ended in a fault failed, for a person.
std::string faultMessage(RunEnd end);

}  // namespace cosim
