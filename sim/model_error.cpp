#include "sim/model_error.h"

namespace cosim {

QuadrotorParams believedAirframe(const QuadrotorParams& truth, const ModelError& e) {
  QuadrotorParams b = truth;
  b.mass *= e.mass;
  b.inertia *= e.inertia;
  b.thrust_coefficient *= e.thrust_coefficient;
  b.min_thrust *= e.thrust_coefficient;
  b.max_thrust *= e.thrust_coefficient;
  return b;
}

}  // namespace cosim
