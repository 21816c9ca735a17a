#include "experiments/compare/reference_alignment.h"

#include <algorithm>
#include <cmath>

namespace cosim {

namespace {

// J(tau) on every `stride`-th sample.
double misfit(const AlignmentProblem& pr, double tau, std::size_t stride, Eigen::Vector3d* d_out) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  double squares = 0.0;
  std::size_t n = 0;
  for (std::size_t k = 0; k < pr.s.size(); k += stride, ++n) {
    const Eigen::Vector3d diff = pr.log->at(pr.s[k] + tau) - pr.target[k];
    sum += diff;
    squares += diff.squaredNorm();
  }
  const Eigen::Vector3d d = pr.fit_translation ? Eigen::Vector3d(sum / n) : Eigen::Vector3d::Zero();
  if (d_out) *d_out = d;
  return std::max(0.0, squares / n - d.squaredNorm());
}

}  // namespace

void offsetRange(const AlignmentProblem& pr, double& lo, double& hi) {
  lo = pr.log->start() - pr.s.front();
  hi = pr.log->end() - pr.s.back();
}

Alignment evaluateAlignment(const AlignmentProblem& pr, double time_offset) {
  Alignment a;
  a.time_offset = time_offset;
  a.rms = std::sqrt(misfit(pr, time_offset, 1, &a.translation));
  return a;
}

Alignment fitAlignment(const AlignmentProblem& pr) {
  double lo, hi;
  offsetRange(pr, lo, hi);
  const std::size_t stride = std::max<std::size_t>(1, pr.s.size() / kCoarseSamples);
  const std::size_t steps = std::clamp<std::size_t>(
      static_cast<std::size_t>(std::ceil((hi - lo) / kCoarseStep)), 1, kMaxCoarseSteps);
  const double h = (hi - lo) / static_cast<double>(steps);
  std::size_t best = 0;
  double best_j = misfit(pr, lo, stride, nullptr);
  for (std::size_t i = 1; i <= steps; ++i) {
    const double j = misfit(pr, i == steps ? hi : lo + i * h, stride, nullptr);
    if (j < best_j) best_j = j, best = i;
  }
  // Golden section on [best - h, best + h] (within the range), every sample.
  double a = std::max(lo, lo + (static_cast<double>(best) - 1.0) * h);
  double b = std::min(hi, lo + (static_cast<double>(best) + 1.0) * h);
  const double ratio = (std::sqrt(5.0) - 1.0) / 2.0;
  double c = b - ratio * (b - a), d = a + ratio * (b - a);
  double jc = misfit(pr, c, 1, nullptr), jd = misfit(pr, d, 1, nullptr);
  while (b - a > kOffsetTolerance) {
    if (jc <= jd) {
      b = d, d = c, jd = jc;
      c = b - ratio * (b - a);
      jc = misfit(pr, c, 1, nullptr);
    } else {
      a = c, c = d, jc = jd;
      d = a + ratio * (b - a);
      jd = misfit(pr, d, 1, nullptr);
    }
  }
  // The bracket's ends too: the optimum may sit on the range's edge.
  Alignment out = evaluateAlignment(pr, 0.5 * (a + b));
  for (const double edge : {lo + std::max(0.0, static_cast<double>(best) - 1.0) * h,
                            std::min(hi, lo + (static_cast<double>(best) + 1.0) * h)}) {
    const Alignment e = evaluateAlignment(pr, edge);
    if (e.rms < out.rms) out = e;
  }
  return out;
}

}  // namespace cosim
