#pragma once
// Segment durations for a minimum-snap trajectory (Mellinger and Kumar 2011, "Minimum snap
// trajectory generation and control for quadrotors", Sec. IV; Richter, Bry and Roy 2013, Sec. 5):
// minimise J(T) + k_T sum_i T_i over the durations T, where J is the snap cost of the optimal fit
// for T (MinimumSnapClosedForm). NLopt's L-BFGS on log T (durations stay positive without bounds)
// with the closed-form gradient.
//
// J(a T) = a^-7 J(T) (snap cost is homogeneous in time), so at the optimum 7 J = k_T sum_i T_i
// and the optimal *relative* allocation does not depend on k_T: k_T only sets the overall pace,
// which a uniform time scaling against the vehicle's limits may then override.
#include <vector>

#include "core/stop_token.h"
#include "planning/trajectory/minimum_snap_closed_form.h"

namespace cosim {

struct TimeAllocationResult {
  std::vector<double> durations;
  double initial_cost = 0.0;  // J + k_T sum T at the start point
  double final_cost = 0.0;    // the same at the returned durations
  int evaluations = 0;        // cost and gradient evaluations
  bool stopped = false;       // the stop token expired: NLopt was stopped (force_stop)
};

// Durations proportional to segment length, at the common pace that minimises J + k_T sum T
// for that shape: T_i = a L_i with a^8 = 7 J(L) / (k_T sum_i L_i).
std::vector<double> distanceProportionalTimes(const MinimumSnapClosedForm& fit,
                                              double time_penalty);

// Starts from `initial` and stops after `max_evaluations` or when the cost changes by less than
// a relative 1e-6 (the result is never worse than `initial`). With `stop`, NLopt is also stopped
// (force_stop) at the first cost evaluation after it expired: the durations are then the best
// found so far.
TimeAllocationResult optimizeSegmentTimes(const MinimumSnapClosedForm& fit,
                                          const std::vector<double>& initial, double time_penalty,
                                          int max_evaluations, const StopToken* stop = nullptr);

}  // namespace cosim
