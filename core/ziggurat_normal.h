#pragma once
// Standard normal numbers by the ziggurat method of G. Marsaglia and W. W. Tsang, "The Ziggurat
// Method for Generating Random Variables", Journal of Statistical Software 5(8), 2000: the area
// under the density is covered by 256 layers of equal area v (255 rectangles stacked on a base
// strip that takes in the tail beyond r). A draw picks a layer and a point in it from one 64-bit
// number; the point lies under the density about 99 % of the time and is returned at once; only
// the rest tests exp(-x^2 / 2), and the base strip's tail beyond r is drawn by Marsaglia's
// exponential method (G. Marsaglia, "Generating a variable from the tail of the normal
// distribution", Technometrics 6(1), 1964), as the paper prescribes. With r = 3.6541528853610088
// and v = r f(r) + the tail's area (f(x) = exp(-x^2 / 2)) the layers close exactly at the peak:
// the paper's constants for 256 layers.
//
// Used for sensor noise, where std::normal_distribution's polar method (a logarithm and a square
// root for every pair of draws, and a rejection loop) was a measurable part of a flight's cost.
// Deterministic: the same engine state gives the same numbers.
#include <cmath>
#include <cstdint>

namespace cosim {

class ZigguratNormal {
 public:
  ZigguratNormal() : t_(&tables()) {}

  // One N(0, 1) number from `engine`, whose operator() gives 64 uniform random bits (e.g.
  // std::mt19937_64).
  template <class Engine>
  double operator()(Engine& engine) const {
    const Tables& t = *t_;
    for (;;) {
      const std::uint64_t bits = engine();
      const int i = static_cast<int>(bits & 0xFF);  // the layer: bits 0-7
      // The sign, bit 8, as a factor of +-1: a branch on it would be mispredicted half the time.
      const double sign = 1.0 - 2.0 * static_cast<double>((bits >> 8) & 1);
      // Bits 11-63, below 2^53: converted as a signed integer (one instruction; an unsigned
      // 64-bit conversion takes several without AVX-512), the same value.
      const double u = static_cast<double>(static_cast<std::int64_t>(bits >> 11)) * 0x1.0p-53;
      const double x = u * t.x[i];
      if (x < t.x[i + 1]) return sign * x;  // inside the layer's core: under f
      if (i == 0) return sign * (t.r + tailExcess(engine, t.r));
      // The layer's edge, beside the density: accept by comparing with f itself.
      const double y = t.f[i] + uniform(engine) * (t.f[i + 1] - t.f[i]);
      if (y < std::exp(-0.5 * x * x)) return sign * x;
    }
  }

  // The layers' right edges x[0..256] (x[0] = v / f(r) the base strip's, x[1] = r, x[256] = 0)
  // and f at them, for tests.
  static constexpr int kLayers = 256;
  static double edge(int i) { return tables().x[i]; }
  static double layerArea() { return tables().v; }

 private:
  struct Tables {
    double r, v;
    double x[kLayers + 1];
    double f[kLayers + 1];
  };
  static const Tables& tables();
  const Tables* t_;

  // Uniform on (0, 1], 53 bits.
  template <class Engine>
  static double uniform(Engine& engine) {
    return static_cast<double>(static_cast<std::int64_t>((engine() >> 11) + 1)) * 0x1.0p-53;
  }
  // The excess over r of a draw from the normal's tail beyond r (Marsaglia 1964).
  template <class Engine>
  static double tailExcess(Engine& engine, double r) {
    for (;;) {
      const double x = -std::log(uniform(engine)) / r;
      const double y = -std::log(uniform(engine));
      if (y + y >= x * x) return x;
    }
  }
};

}  // namespace cosim
