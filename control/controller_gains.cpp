#include "control/controller_gains.h"

#include <sstream>

namespace cosim {

namespace {

// As ParamSet shows values (12 significant digits), so the listing's default is the text a
// scenario's value is compared with.
std::string gainText(double v) {
  std::ostringstream out;
  out.precision(12);
  out << v;
  return out.str();
}

GainKey keyOf(const GainDeclaration& d, const std::string& suffix, double default_value,
              const std::string& axes) {
  // (appended piecewise: GCC 12 warns falsely on "..." + std::string, -Wrestrict)
  std::string range;
  range.append("[").append(gainText(d.lo)).append(", ").append(gainText(d.hi)).append("]");
  return {d.name + suffix, d.absent_means.empty() ? gainText(default_value) : d.absent_means, range,
          axes.empty() ? d.doc : d.doc + " (" + axes + ")"};
}

}  // namespace

std::vector<GainKey> gainKeys(const std::vector<GainDeclaration>& declared) {
  std::vector<GainKey> keys;
  for (const GainDeclaration& d : declared) {
    const double shared = d.default_value.x(), own = d.default_value.z();
    switch (d.axes) {
      case GainAxes::Single:
        keys.push_back(keyOf(d, "", shared, ""));
        break;
      case GainAxes::HorizontalAndZ:
        keys.push_back(keyOf(d, "_xy", shared, "x and y"));
        keys.push_back(keyOf(d, "_z", own, "z"));
        break;
      case GainAxes::RollPitchAndYaw:
        keys.push_back(keyOf(d, "_rp", shared, "roll and pitch"));
        keys.push_back(keyOf(d, "_yaw", own, "yaw"));
        break;
    }
  }
  return keys;
}

}  // namespace cosim
