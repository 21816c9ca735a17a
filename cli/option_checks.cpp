#include "cli/option_checks.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace cosim::cli {

namespace {

std::string shortNumber(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

}  // namespace

CLI::Validator numberIn(double lo, double hi) {
  return CLI::Validator(
      [lo, hi](std::string& input) -> std::string {
        char* end = nullptr;
        const double v = std::strtod(input.c_str(), &end);
        if (input.empty() || *end != '\0' || !std::isfinite(v) || v < lo || v > hi)
          return "must be a number from " + shortNumber(lo) + " to " + shortNumber(hi) + ", got '" +
                 input + "'";
        return "";
      },
      "number in [" + shortNumber(lo) + ", " + shortNumber(hi) + "]");
}

CLI::Validator wholeNumberIn(long lo, long hi) {
  return CLI::Validator(
      [lo, hi](std::string& input) -> std::string {
        char* end = nullptr;
        errno = 0;
        const long v = std::strtol(input.c_str(), &end, 10);
        if (input.empty() || *end != '\0' || errno == ERANGE || v < lo || v > hi)
          return "must be a whole number from " + std::to_string(lo) + " to " + std::to_string(hi) +
                 ", got '" + input + "'";
        return "";
      },
      "whole number in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
}

}  // namespace cosim::cli
