#pragma once
// One identified constant with its uncertainty, and the data behind a fit's figure.
#include <string>
#include <vector>

namespace cosim {

struct IdentifiedValue {
  bool identified = false;
  double value = 0.0;
  double ci_low = 0.0, ci_high = 0.0;  // the 95 % confidence interval
  double residual = 0.0;               // the fit's RMS residual, in residual_unit
  std::string unit, residual_unit;
  std::size_t samples = 0;
  std::string method;   // how, in a few words (for the report)
  std::string not_why;  // why it was not identified (when !identified)
};

// Points of one fit for its figure: the measured y and the fitted model's y at each x.
struct FitFigure {
  std::string name;  // file stem, e.g. "motor_map"
  std::string title, xlabel, ylabel;
  std::vector<double> x, measured, fitted;
};

}  // namespace cosim
