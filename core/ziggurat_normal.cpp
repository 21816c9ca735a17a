#include "core/ziggurat_normal.h"

namespace cosim {

const ZigguratNormal::Tables& ZigguratNormal::tables() {
  // Built once (a function-local static: thread-safe), from the paper's r for 256 layers.
  static const Tables t = [] {
    Tables b{};
    const auto f = [](double x) { return std::exp(-0.5 * x * x); };
    b.r = 3.6541528853610088;
    // Each layer's area: the base strip's rectangle r f(r) plus the tail's area,
    // integral_r^inf f = sqrt(pi / 2) erfc(r / sqrt 2); 4.92867323399e-3 in the paper.
    b.v = b.r * f(b.r) + std::sqrt(M_PI / 2.0) * std::erfc(b.r / std::sqrt(2.0));
    b.x[0] = b.v / f(b.r);
    b.x[1] = b.r;
    // Layer i spans heights f(x[i]) to f(x[i + 1]) over [0, x[i]] with area v:
    // f(x[i + 1]) = f(x[i]) + v / x[i].
    for (int i = 1; i < kLayers - 1; ++i)
      b.x[i + 1] = std::sqrt(-2.0 * std::log(f(b.x[i]) + b.v / b.x[i]));
    b.x[kLayers] = 0.0;  // the top layer reaches the peak, f = 1
    for (int i = 0; i <= kLayers; ++i) b.f[i] = f(b.x[i]);
    return b;
  }();
  return t;
}

}  // namespace cosim
