#include "run/run_end.h"

namespace cosim {

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
