#pragma once
// How close a run's quadrotors came to each other, from the run log: contacts between two of
// them (MuJoCo's, booked by sim/contact_monitor.h), the smallest ellipsoidal distance between any
// two at the logged instants (planning/team/separation_ellipsoid.h: 1.0 is touching the
// ellipsoid, so a smaller figure is a violation), and the number of times a pair entered its
// ellipsoid (each entry counted once, however long it stayed).
#include <limits>
#include <vector>

#include "planning/team/separation_ellipsoid.h"
#include "sim/run_log.h"

namespace cosim {

struct UavSeparationMetrics {
  int uav_contacts = 0;
  double min_uav_separation = std::numeric_limits<double>::infinity();
  int downwash_violations = 0;
};

// `quadrotors`: the indices into log.vehicles of the quadrotors; `separation[k]` the ellipsoid
// of quadrotors[k]'s model. All of them must be logged at the same instants.
UavSeparationMetrics uavSeparationMetrics(const RunLog& log,
                                          const std::vector<std::size_t>& quadrotors,
                                          const std::vector<SeparationEllipsoid>& separation);

}  // namespace cosim
