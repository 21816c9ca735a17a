#include "planning/trajectory/segment_time_allocation.h"

#include <cmath>
#include <nlopt.hpp>
#include <numeric>

namespace cosim {
namespace {

struct Objective {
  const MinimumSnapClosedForm* fit;
  double time_penalty;
  double normaliser;  // the initial cost: NLopt's tolerances then act on a number near 1
  const StopToken* stop;
  int evaluations = 0;
  std::vector<double> T, dJ;

  // x_i = log T_i; f = J(T) + k_T sum T; df/dx_i = (dJ/dT_i + k_T) T_i.
  double operator()(const std::vector<double>& x, std::vector<double>& grad) {
    // NLopt's C++ wrapper turns this into force_stop; optimize() then throws it back to us.
    if (stop != nullptr && stop->expired()) throw nlopt::forced_stop();
    ++evaluations;
    for (std::size_t i = 0; i < x.size(); ++i) T[i] = std::exp(x[i]);
    const double J = fit->cost(T, grad.empty() ? nullptr : &dJ);
    for (std::size_t i = 0; i < grad.size(); ++i)
      grad[i] = (dJ[i] + time_penalty) * T[i] / normaliser;
    return (J + time_penalty * std::accumulate(T.begin(), T.end(), 0.0)) / normaliser;
  }
  static double call(const std::vector<double>& x, std::vector<double>& grad, void* data) {
    return (*static_cast<Objective*>(data))(x, grad);
  }
};

double totalCost(const MinimumSnapClosedForm& fit, const std::vector<double>& T, double k_T) {
  return fit.cost(T) + k_T * std::accumulate(T.begin(), T.end(), 0.0);
}

}  // namespace

std::vector<double> distanceProportionalTimes(const MinimumSnapClosedForm& fit,
                                              double time_penalty) {
  const auto& w = fit.waypoints();
  std::vector<double> L(fit.segmentCount());
  for (std::size_t i = 0; i < L.size(); ++i) L[i] = (w[i + 1] - w[i]).norm();
  const double J = fit.cost(L);
  const double a =
      std::pow(7.0 * J / (time_penalty * std::accumulate(L.begin(), L.end(), 0.0)), 1.0 / 8.0);
  for (double& t : L) t *= a;
  return L;
}

TimeAllocationResult optimizeSegmentTimes(const MinimumSnapClosedForm& fit,
                                          const std::vector<double>& initial, double time_penalty,
                                          int max_evaluations, const StopToken* stop) {
  TimeAllocationResult result;
  result.durations = initial;
  result.initial_cost = result.final_cost = totalCost(fit, initial, time_penalty);
  const std::size_t n = initial.size();

  Objective objective{&fit, time_penalty,           result.initial_cost, stop,
                      0,    std::vector<double>(n), std::vector<double>(n)};
  nlopt::opt optimizer(nlopt::LD_LBFGS, static_cast<unsigned>(n));
  optimizer.set_min_objective(&Objective::call, &objective);
  optimizer.set_ftol_rel(1e-6);
  optimizer.set_maxeval(max_evaluations);
  std::vector<double> x(n);
  for (std::size_t i = 0; i < n; ++i) x[i] = std::log(initial[i]);
  double value = 0.0;
  try {
    optimizer.optimize(x, value);
  } catch (const nlopt::roundoff_limited&) {
    // Converged as far as floating point allows; x holds the best point found.
  } catch (const nlopt::forced_stop&) {
    // Stopped by the token; x holds the best point found so far.
    result.stopped = true;
  } catch (const std::runtime_error&) {
    // NLopt's generic failure: keep the initial durations rather than a half-made step.
    result.evaluations = objective.evaluations;
    return result;
  }
  result.evaluations = objective.evaluations;
  std::vector<double> T(n);
  for (std::size_t i = 0; i < n; ++i) T[i] = std::exp(x[i]);
  const double cost = totalCost(fit, T, time_penalty);
  if (cost < result.initial_cost) {
    result.durations = std::move(T);
    result.final_cost = cost;
  }
  return result;
}

}  // namespace cosim
