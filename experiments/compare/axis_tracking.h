#pragma once
// How a flight follows its reference along each axis: its lag and its amplitude ratio, so that a
// comparison says *how* a flight differs from its reference (late, or cutting the corners short)
// and not only by how much.
//
// For axis a, with the reference r_a at times s_k (a window of it) and the flight f_a read by
// linear interpolation on the reference's clock:
//   lag_a = argmin over delta in [-kMaxAxisLag, kMaxAxisLag] of
//           1/N sum_k (f_a(s_k + delta) - r_a(s_k) - m(delta))^2,
//     m(delta) the mean of f_a(s_k + delta) - r_a(s_k) (a constant offset is not a lag):
//     positive when the flight is late;
//   amplitude_ratio_a = sum_k (f_a(s_k + lag_a) - mean f)(r_a(s_k) - mean r) / sum_k (r_a - mean
//   r)^2,
//     the least-squares gain of the lag-corrected flight on the reference (1: full size; 0.9: the
//     flight's excursions are 10 % short of the reference's).
// Only the s_k from which the flight is defined kMaxAxisLag either side enter, so that every
// delta is judged on the same samples. An axis along which the reference moves less than
// kStillAxisExtent (peak to peak) has neither (NaN): there is nothing to be late for; so have all
// axes when fewer than kMinAxisSamples samples remain. The search: a scan in kAxisLagStep steps
// on at most kCoarseAxisSamples of the s_k, then a golden-section search (Kiefer 1953) on all of
// them over the two steps around the best.
#include <Eigen/Core>
#include <limits>
#include <vector>

#include "core/stop_token.h"
#include "experiments/compare/sampled_path.h"

namespace cosim {

constexpr double kMaxAxisLag = 0.5;        // s: a quadrotor's position loop lags ~0.1-0.3 s
constexpr double kAxisLagStep = 0.001;     // s
constexpr double kStillAxisExtent = 1e-3;  // m
constexpr std::size_t kMinAxisSamples = 10;
constexpr std::size_t kCoarseAxisSamples = 400;

struct AxisTracking {
  Eigen::Vector3d lag_s = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
  Eigen::Vector3d amplitude_ratio =
      Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
};

// `reference_t`/`reference_p`: the reference's samples over the window judged; `flight`: the
// flight on the same clock. Throws AlignmentInterrupted (reference_alignment.h) when `stop`
// expires.
AxisTracking axisTracking(const std::vector<double>& reference_t,
                          const std::vector<Eigen::Vector3d>& reference_p,
                          const SampledPath& flight, const StopToken& stop = StopToken::untimed());

}  // namespace cosim
