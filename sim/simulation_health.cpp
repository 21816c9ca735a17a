#include "sim/simulation_health.h"

#include <cmath>
#include <initializer_list>

namespace cosim {

bool stateIsFinite(const mjModel* m, const mjData* d) {
  for (int i = 0; i < m->nq; ++i)
    if (!std::isfinite(d->qpos[i])) return false;
  return true;
}

bool mujocoFoundBadNumbers(const mjData* d) {
  for (int w : {mjWARN_BADQPOS, mjWARN_BADQVEL, mjWARN_BADQACC, mjWARN_BADCTRL})
    if (d->warning[w].number > 0) return true;
  return false;
}

std::optional<RunEnd> physicsFault(const mjModel* m, const mjData* d) {
  if (!stateIsFinite(m, d)) return RunEnd::Diverged;
  if (mujocoFoundBadNumbers(d)) return RunEnd::Unstable;
  return std::nullopt;
}

}  // namespace cosim
