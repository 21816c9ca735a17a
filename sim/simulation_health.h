#pragma once
// Checks after a physics step that the simulation can still be trusted.
#include <mujoco/mujoco.h>

namespace cosim {

// Every generalised coordinate is a finite number.
bool stateIsFinite(const mjModel* m, const mjData* d);

// MuJoCo's answer to a NaN or huge number in the state or the controls is a warning and a reset of
// the data (or zeroed controls): a vehicle would jump back to its start and the log go on as if
// nothing happened. True once MuJoCo has done so.
bool mujocoFoundBadNumbers(const mjData* d);

// The run's end_reason if the step just taken cannot be trusted: "diverged" (a non-finite
// coordinate), "unstable" (MuJoCo found bad numbers); nullptr if it can.
const char* physicsFault(const mjModel* m, const mjData* d);

}  // namespace cosim
