#pragma once
// Placing a flight log on a run's clock (and, optionally, in its frame) by least squares.
//
// The run gives target positions r_k at its times s_k (inside the reference's window); the log
// gives a path L(t) on its own clock. For a time offset tau (log time minus run time) and a
// translation d (log frame minus run frame), the misfit is
//     J(tau, d) = 1/N sum_k |L(s_k + tau) - d - r_k|^2,
// with L read by linear interpolation. For a given tau the best d is the mean of
// L(s_k + tau) - r_k (setting dJ/dd = 0), which leaves J(tau) = mean|L - r|^2 - |d|^2; without
// a translation d = 0. J(tau) is minimised over every offset at which the log covers the whole
// window: a coarse scan (steps of kCoarseStep, or more for a long log: at most kMaxCoarseSteps,
// on at most kCoarseSamples of the s_k),
// then a golden-section search (Kiefer 1953) over the two steps around the best point, on all s_k.
#include <Eigen/Core>
#include <vector>

#include "experiments/compare/sampled_path.h"

namespace cosim {

struct AlignmentProblem {
  std::vector<double> s;                // run times, increasing
  std::vector<Eigen::Vector3d> target;  // r_k
  const SampledPath* log = nullptr;     // L
  bool fit_translation = false;
};

struct Alignment {
  double time_offset = 0.0;                               // tau, s
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();  // d, m
  double rms = 0.0;                                       // sqrt(J) at the optimum, m
};

constexpr double kCoarseStep = 0.002;  // s
constexpr std::size_t kMaxCoarseSteps = 20000;
constexpr std::size_t kCoarseSamples = 400;
constexpr double kOffsetTolerance = 1e-6;  // s, the golden-section search's bracket at the end

// The offsets at which the log covers [s.front(), s.back()]: [lo, hi]; lo > hi if none.
void offsetRange(const AlignmentProblem& problem, double& lo, double& hi);

// J and d at a given offset.
Alignment evaluateAlignment(const AlignmentProblem& problem, double time_offset);

// The least-squares offset (and translation). Requires a non-empty offset range.
Alignment fitAlignment(const AlignmentProblem& problem);

}  // namespace cosim
