#include "experiments/compare/reference_alignment.h"

#include <algorithm>
#include <cmath>
#include <limits>

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
  Eigen::Vector3d d = Eigen::Vector3d::Zero();
  if (pr.translation != FittedTranslation::None) d = sum / static_cast<double>(n);
  if (pr.translation == FittedTranslation::XY) d.z() = 0.0;
  if (d_out) *d_out = d;
  return std::max(0.0, squares / static_cast<double>(n) - d.squaredNorm());
}

// J at `tau`, after making sure nobody asked to stop.
double checkedMisfit(const AlignmentProblem& pr, double tau, std::size_t stride,
                     const StopToken& stop) {
  if (stop.expired()) throw AlignmentInterrupted();
  return misfit(pr, tau, stride, nullptr);
}

struct CoarseBest {
  double tau = 0.0, j = std::numeric_limits<double>::infinity();
  OffsetInterval interval;
};

// The scan: every interval at spacing h (its ends included), on every stride-th run sample.
CoarseBest coarseScan(const AlignmentProblem& pr, const std::vector<OffsetInterval>& intervals,
                      double h, std::size_t stride, const StopToken& stop) {
  CoarseBest best;
  const auto consider = [&](double tau, const OffsetInterval& iv) {
    const double j = checkedMisfit(pr, tau, stride, stop);
    if (j < best.j) best = CoarseBest{tau, j, iv};
  };
  for (const OffsetInterval& iv : intervals) {
    const std::size_t inner =
        h > 0.0 ? static_cast<std::size_t>(std::floor((iv.hi - iv.lo) / h)) : 0;
    for (std::size_t i = 0; i <= inner; ++i) consider(iv.lo + static_cast<double>(i) * h, iv);
    if (iv.hi > iv.lo) consider(iv.hi, iv);
  }
  return best;
}

}  // namespace

void offsetRange(const AlignmentProblem& pr, double& lo, double& hi) {
  lo = pr.log->start() - pr.s.front();
  hi = pr.log->end() - pr.s.back();
}

std::vector<OffsetInterval> searchedOffsets(const AlignmentProblem& pr) {
  double lo, hi;
  offsetRange(pr, lo, hi);
  std::vector<OffsetInterval> out;
  const std::vector<double>& t = pr.log->t;
  if (lo > hi || t.size() < kMinWindowLogSamples) return out;
  // Samples i .. i+K-1 lie in the shifted window when t[i+K-1] - s_end <= tau <= t[i] - s_begin;
  // both ends grow with i, so overlapping intervals are neighbours.
  for (std::size_t i = 0; i + kMinWindowLogSamples <= t.size(); ++i) {
    const double a = std::max(lo, t[i + kMinWindowLogSamples - 1] - pr.s.back());
    const double b = std::min(hi, t[i] - pr.s.front());
    if (a > b) continue;
    if (!out.empty() && a <= out.back().hi)
      out.back().hi = std::max(out.back().hi, b);
    else
      out.push_back({a, b});
  }
  return out;
}

Alignment evaluateAlignment(const AlignmentProblem& pr, double time_offset) {
  Alignment a;
  a.time_offset = time_offset;
  a.rms = std::sqrt(misfit(pr, time_offset, 1, &a.translation));
  return a;
}

Alignment fitAlignment(const AlignmentProblem& pr, const StopToken& stop) {
  const std::vector<OffsetInterval> intervals = searchedOffsets(pr);
  if (intervals.empty()) throw std::invalid_argument("fitAlignment: no offset to search");
  double total = 0.0;
  for (const OffsetInterval& iv : intervals) total += iv.hi - iv.lo;
  const std::size_t stride = std::max<std::size_t>(1, pr.s.size() / kCoarseSamples);
  const std::size_t steps = std::clamp<std::size_t>(
      static_cast<std::size_t>(std::ceil(total / kCoarseStep)), 1, kMaxCoarseSteps);
  const double h = total / static_cast<double>(steps);
  const CoarseBest best = coarseScan(pr, intervals, h, stride, stop);
  // Golden section on [best - h, best + h] (within its interval), every sample, for as many
  // steps as bring the bracket down to the tolerance or to a few units in the last place of the
  // offsets (a bracket below that cannot shrink any more).
  double a = std::max(best.interval.lo, best.tau - h);
  double b = std::min(best.interval.hi, best.tau + h);
  const double ratio = (std::sqrt(5.0) - 1.0) / 2.0;
  const double tolerance = std::max(kOffsetTolerance, 8.0 * std::numeric_limits<double>::epsilon() *
                                                          std::max(std::abs(a), std::abs(b)));
  const int golden_steps =
      b - a > tolerance
          ? static_cast<int>(std::ceil(std::log(tolerance / (b - a)) / std::log(ratio)))
          : 0;
  double c = b - ratio * (b - a), d = a + ratio * (b - a);
  double jc = checkedMisfit(pr, c, 1, stop), jd = checkedMisfit(pr, d, 1, stop);
  for (int i = 0; i < golden_steps; ++i) {
    if (jc <= jd) {
      b = d, d = c, jd = jc;
      c = b - ratio * (b - a);
      jc = checkedMisfit(pr, c, 1, stop);
    } else {
      a = c, c = d, jc = jd;
      d = a + ratio * (b - a);
      jd = checkedMisfit(pr, d, 1, stop);
    }
  }
  // The bracket's ends too: the optimum may sit on the edge of what is searched.
  Alignment out = evaluateAlignment(pr, 0.5 * (a + b));
  for (const double edge :
       {std::max(best.interval.lo, best.tau - h), std::min(best.interval.hi, best.tau + h)}) {
    const Alignment e = evaluateAlignment(pr, edge);
    if (e.rms < out.rms) out = e;
  }
  return out;
}

}  // namespace cosim
