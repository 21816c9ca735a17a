#include "experiments/compare/alignment_mode.h"

namespace cosim {

const char* alignModeName(AlignMode mode) {
  switch (mode) {
    case AlignMode::None:
      return "none";
    case AlignMode::Time:
      return "time";
    case AlignMode::TimeXY:
      return "time+xy";
    case AlignMode::TimeXYZ:
      return "time+xyz";
  }
  return "none";
}

std::optional<AlignMode> alignModeNamed(const std::string& name) {
  for (const AlignMode m : allAlignModes())
    if (name == alignModeName(m)) return m;
  return std::nullopt;
}

const std::vector<AlignMode>& allAlignModes() {
  static const std::vector<AlignMode> modes = {AlignMode::None, AlignMode::Time, AlignMode::TimeXY,
                                               AlignMode::TimeXYZ};
  return modes;
}

bool fitsTime(AlignMode mode) {
  return mode != AlignMode::None;
}

FittedTranslation fittedTranslation(AlignMode mode) {
  if (mode == AlignMode::TimeXY) return FittedTranslation::XY;
  if (mode == AlignMode::TimeXYZ) return FittedTranslation::XYZ;
  return FittedTranslation::None;
}

bool fitsAxis(AlignMode mode, int axis) {
  return mode == AlignMode::TimeXYZ || (mode == AlignMode::TimeXY && axis < 2);
}

AlignMode defaultAlignMode(bool log_has_reference) {
  return log_has_reference ? AlignMode::TimeXY : AlignMode::Time;
}

}  // namespace cosim
