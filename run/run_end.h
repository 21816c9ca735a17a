#pragma once
// Why a run's simulation ended, as an enum for the pipeline's decisions. The simulation loops
// (sim/) record it as RunLog::end_reason, a string, which metrics.json keeps as it is.
#include <string>

namespace cosim {

enum class RunEnd {
  Goal,         // every vehicle reached its goal and held it
  MaxTime,      // sim.max_time ran out
  Interrupted,  // SIGINT/SIGTERM (the run's interrupt flag)
  Diverged,     // NaN or runaway state
  Unstable,     // MuJoCo found bad numbers in the state or controls
  Saturated,    // a quadrotor's rotors stayed saturated too long
  GaveUp,       // the navigator gave up
  NoPath,       // not simulated: a vehicle had no plan to follow
  Other,        // a reason this version does not know
};

// The end_reason a run writes when it did not simulate because planning failed.
inline constexpr const char* kNoPathEndReason = "no_path";

RunEnd runEndOf(const std::string& end_reason);

// A fault of the simulated vehicles (metrics.json's "fault"): diverged, unstable or saturated.
bool isFault(RunEnd end);

// Why a run whose simulation ended in a fault failed, for a person.
std::string faultMessage(RunEnd end);

}  // namespace cosim
