#include "run/run_end.h"

namespace cosim {

RunEnd runEndOf(const std::string& end_reason) {
  if (end_reason == "goal") return RunEnd::Goal;
  if (end_reason == "max_time") return RunEnd::MaxTime;
  if (end_reason == "interrupted") return RunEnd::Interrupted;
  if (end_reason == "diverged") return RunEnd::Diverged;
  if (end_reason == "unstable") return RunEnd::Unstable;
  if (end_reason == "saturated") return RunEnd::Saturated;
  if (end_reason == "gave_up") return RunEnd::GaveUp;
  if (end_reason == kNoPathEndReason) return RunEnd::NoPath;
  return RunEnd::Other;
}

bool isFault(RunEnd end) {
  return end == RunEnd::Diverged || end == RunEnd::Unstable || end == RunEnd::Saturated;
}

std::string faultMessage(RunEnd end) {
  switch (end) {
    case RunEnd::Diverged:
      return "the simulation diverged (NaN or runaway state)";
    case RunEnd::Unstable:
      return "the simulation became unstable (MuJoCo found bad numbers in the state or controls)";
    case RunEnd::Saturated:
      return "the rotors stayed saturated for over 2 s: the vehicle cannot follow its reference "
             "(check controller gains, trajectory limits, the model's mass and thrust)";
    default:
      return "";
  }
}

}  // namespace cosim
