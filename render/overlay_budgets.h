#pragma once
// How many line pieces a rendered frame may add: geoms added per frame are capped, since
// software rendering pays per triangle and a capsule is a few hundred. The trail and the
// reference are decimated to stay within these budgets.
#include <algorithm>
#include <cstddef>

namespace cosim {

constexpr int kTrailSegmentBudget = 250;
constexpr int kReferenceDashBudget = 60;
// With many vehicles every vehicle's trail shares this many segments. As capsules, 250 each (a
// 20-robot team) cost about 0.4 s a frame in software; a team's trails are now ribbons in one
// draw call (render/ribbon_batch.h), where 4000 segments for 32 Crazyflies cost a few ms
// (cosim bench --section team_render).
constexpr int kTeamTrailSegmentBudget = 4000;

// The trail segments each of `vehicles` vehicles may draw.
inline int trailBudget(std::size_t vehicles) {
  return std::max(20,
                  std::min(kTrailSegmentBudget,
                           kTeamTrailSegmentBudget / std::max<int>(1, static_cast<int>(vehicles))));
}

}  // namespace cosim
