#pragma once
// What compare-real fits when it places a log beside a run (--align): nothing, the time offset,
// the time offset and a horizontal translation, or the time offset and a full translation.
// Whatever is fitted is taken out of the real error; the comparison reports it beside the result
// (mean_offset_m, rmse_by_alignment), so nothing fitted away goes unseen.
#include <optional>
#include <string>
#include <vector>

#include "experiments/compare/reference_alignment.h"

namespace cosim {

enum class AlignMode { None, Time, TimeXY, TimeXYZ };

// "none", "time", "time+xy", "time+xyz".
const char* alignModeName(AlignMode mode);
std::optional<AlignMode> alignModeNamed(const std::string& name);
const std::vector<AlignMode>& allAlignModes();

bool fitsTime(AlignMode mode);
FittedTranslation fittedTranslation(AlignMode mode);
// Whether the mode fits the translation along axis 0 (x), 1 (y) or 2 (z).
bool fitsAxis(AlignMode mode, int axis);

// The default: `time` for a log without a reference; with one, `time+xy` (its reference placed
// in time and in the horizontal frame by the run's reference). Height is never fitted unless
// asked: a real vehicle flying high is an error the comparison must show.
AlignMode defaultAlignMode(bool log_has_reference);

}  // namespace cosim
