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

CLI::Validator seedNumber() {
  return CLI::Validator(
      [](std::string& input) -> std::string {
        const bool digits = !input.empty() && input.size() <= 20 &&
                            input.find_first_not_of("0123456789") == std::string::npos;
        errno = 0;
        if (digits) std::strtoull(input.c_str(), nullptr, 10);
        if (!digits || errno == ERANGE)
          return "must be a whole number from 0 to 18446744073709551615, got '" + input + "'";
        return "";
      },
      "whole number in [0, 2^64 - 1]");
}

}  // namespace cosim::cli
