#include "sim/error_reference.h"

namespace cosim {

const char* errorReferenceKey(ErrorReference r) {
  switch (r) {
    case ErrorReference::TimedPlan:
      return "timed_plan";
    case ErrorReference::Trajectory:
      return "trajectory";
    case ErrorReference::PlannedPath:
      return "path";
    case ErrorReference::Mixed:
      return "mixed";
    case ErrorReference::None:
      break;
  }
  return "";
}

const char* errorReferenceName(ErrorReference r) {
  switch (r) {
    case ErrorReference::TimedPlan:
      return "timed plan";
    case ErrorReference::Trajectory:
      return "reference trajectory";
    case ErrorReference::PlannedPath:
      return "planned path";
    case ErrorReference::Mixed:
      return "each vehicle's own reference";
    case ErrorReference::None:
      break;
  }
  return "";
}

const char* errorReferenceShortName(ErrorReference r) {
  switch (r) {
    case ErrorReference::TimedPlan:
      return "plan";
    case ErrorReference::Trajectory:
      return "reference";
    case ErrorReference::PlannedPath:
      return "path";
    case ErrorReference::Mixed:
      return "own reference";
    case ErrorReference::None:
      break;
  }
  return "";
}

}  // namespace cosim
