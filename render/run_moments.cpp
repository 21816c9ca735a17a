#include "render/run_moments.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace cosim {

namespace {

std::string fixed(double v, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", digits, v);
  return buf;
}

std::size_t sampleCount(const RunLog& log) {
  std::size_t n = 0;
  for (const auto& v : log.vehicles) n += v.samples.size();
  return n;
}

void closestApproach(const RunLog& log, const World& world, int stride,
                     std::vector<RunMoment>& out) {
  if (world.obstacles.empty() ||
      static_cast<double>(sampleCount(log)) / stride * world.obstacles.size() > kMomentSearchBudget)
    return;
  RunMoment m{"closest_approach", 0.0, -1, -1, std::numeric_limits<double>::infinity(), ""};
  for (std::size_t v = 0; v < log.vehicles.size(); ++v) {
    const VehicleLog& vl = log.vehicles[v];
    for (std::size_t k = 0; k < vl.samples.size(); k += stride) {
      const double c = world.distanceToObstacles(vl.samples[k].pos) - vl.radius;
      if (c < m.value) m = {m.kind, vl.samples[k].t, static_cast<int>(v), -1, c, ""};
    }
  }
  if (m.vehicle < 0) return;
  m.label = "closest approach to an obstacle: " + fixed(m.value, 3) + " m (" +
            log.vehicles[m.vehicle].name + ")";
  out.push_back(m);
}

// Samples of all vehicles at the same instant: pairs are compared sample by sample, which holds
// for vehicles logged together (a team); a vehicle whose log ended is left out from then on.
void closestPair(const RunLog& log, int stride, std::vector<RunMoment>& out) {
  const std::size_t n = log.vehicles.size();
  std::size_t longest = 0;
  for (const auto& v : log.vehicles) longest = std::max(longest, v.samples.size());
  if (n < 2 || 0.5 * n * (n - 1) * static_cast<double>(longest) / stride > kMomentSearchBudget)
    return;
  RunMoment m{"closest_pair", 0.0, -1, -1, std::numeric_limits<double>::infinity(), ""};
  for (std::size_t k = 0; k < longest; k += stride)
    for (std::size_t a = 0; a < n; ++a) {
      const VehicleLog& va = log.vehicles[a];
      if (k >= va.samples.size()) continue;
      for (std::size_t b = a + 1; b < n; ++b) {
        const VehicleLog& vb = log.vehicles[b];
        if (k >= vb.samples.size()) continue;
        const double d = (va.samples[k].pos - vb.samples[k].pos).norm() - va.radius - vb.radius;
        if (d < m.value)
          m = {m.kind, va.samples[k].t, static_cast<int>(a), static_cast<int>(b), d, ""};
      }
    }
  if (m.vehicle < 0) return;
  m.label = "closest pair: " + fixed(m.value, 3) + " m between bodies (" +
            log.vehicles[m.vehicle].name + ", " + log.vehicles[m.other].name + ")";
  out.push_back(m);
}

void worstError(const RunLog& log, std::vector<RunMoment>& out) {
  RunMoment m{"worst_error", 0.0, -1, -1, -1.0, ""};
  for (std::size_t v = 0; v < log.vehicles.size(); ++v)
    for (const LogSample& s : log.vehicles[v].samples) {
      const double e = (s.pos - s.ref_pos).norm();
      if (e > m.value) m = {m.kind, s.t, static_cast<int>(v), -1, e, ""};
    }
  if (m.vehicle < 0) return;
  m.label = "largest error to the reference: " + fixed(m.value, 3) + " m (" +
            log.vehicles[m.vehicle].name + ")";
  out.push_back(m);
}

// What a vehicle hit, as the user names it: the world's geom "obstacle7" is the scenario's
// world.obstacles[7] (numbered from 0, as --set numbers them); other names are the world's own.
std::string hitName(const std::string& geom) {
  const std::string prefix = "obstacle";
  if (geom.size() <= prefix.size() || geom.compare(0, prefix.size(), prefix) != 0) return geom;
  const std::string digits = geom.substr(prefix.size());
  if (digits.find_first_not_of("0123456789") != std::string::npos) return geom;
  return "world.obstacles[" + digits + "]";
}

}  // namespace

std::vector<RunMoment> runMoments(const RunLog& log, const World& world, int stride) {
  stride = std::max(stride, 1);
  std::vector<RunMoment> out;
  closestApproach(log, world, stride, out);
  closestPair(log, stride, out);
  worstError(log, out);
  for (std::size_t v = 0; v < log.vehicles.size(); ++v)
    for (const ContactEvent& c : log.vehicles[v].collisions)
      out.push_back({"collision", c.t, static_cast<int>(v), -1, 0.0,
                     "collision: " + log.vehicles[v].name + " hit " + hitName(c.other)});
  std::stable_sort(out.begin(), out.end(),
                   [](const RunMoment& a, const RunMoment& b) { return a.t < b.t; });
  return out;
}

}  // namespace cosim
