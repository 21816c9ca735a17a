#include "control/controller_gains.h"

namespace cosim {

namespace {

GainKey keyOf(const GainDeclaration& d, const std::string& suffix, double default_value,
              const std::string& axes) {
  // As ParamSet shows values and ranges, so the listing reads as `cosim plan --list` does and
  // its default is the text a scenario's value is compared with.
  return {d.name + suffix, d.absent_means.empty() ? paramNumberText(default_value) : d.absent_means,
          paramNumberRangeText(d.lo, d.hi), axes.empty() ? d.doc : d.doc + " (" + axes + ")"};
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
