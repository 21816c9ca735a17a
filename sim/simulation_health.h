#pragma once
// Checks after a physics step that the simulation can still be trusted.
#include <mujoco/mujoco.h>

#include <optional>

#include "sim/run_log.h"

namespace cosim {

// Every generalised coordinate is a finite number.
bool stateIsFinite(const mjModel* m, const mjData* d);

// MuJoCo's answer to a NaN or huge number in the state or the controls is a warning and a reset of
// the data (or zeroed controls): a vehicle would jump back to its start and the log go on as if
// nothing happened. True once MuJoCo has done so.
bool mujocoFoundBadNumbers(const mjData* d);

// How the run ends if the step just taken cannot be trusted: Diverged (a non-finite
// coordinate), Unstable (MuJoCo found bad numbers); none if it can.
std::optional<RunEnd> physicsFault(const mjModel* m, const mjData* d);

}  // namespace cosim
