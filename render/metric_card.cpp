#include "render/metric_card.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace cosim {

namespace {

bool endsWith(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() &&
         s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

std::string cardText(const char* pattern, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, pattern, v);
  return buf;
}

// Three significant digits, no exponent for the magnitudes metrics have (1e-4 .. 1e5).
std::string significant3(double v) {
  const double a = std::abs(v);
  if (a == 0.0) return "0";
  if (a >= 100.0) return cardText("%.0f", v);
  if (a >= 10.0) return cardText("%.1f", v);
  if (a >= 1.0) return cardText("%.2f", v);
  return cardText("%.3g", v);
}

}  // namespace

std::string cardValue(const std::string& key, const std::string& value) {
  char* end = nullptr;
  const double v = std::strtod(value.c_str(), &end);
  if (value.empty() || end != value.c_str() + value.size() || !std::isfinite(v)) return value;
  if (endsWith(key, "_ms")) return significant3(v) + " ms";
  if (endsWith(key, "_mps")) return significant3(v) + " m/s";
  if (endsWith(key, "_s")) return cardText("%.2f", v) + " s";
  if (endsWith(key, "_m")) {
    // Tracking errors and clearances are centimetres; lengths of paths metres.
    if (std::abs(v) < 1.0) return significant3(100.0 * v) + " cm";
    return cardText("%.2f", v) + " m";
  }
  // Counts (collisions) are integers in metrics.json: as they are.
  if (value.find_first_of(".eE") == std::string::npos) return value;
  return significant3(v);
}

}  // namespace cosim
