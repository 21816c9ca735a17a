#include "sim/contact_monitor.h"

#include <algorithm>
#include <string>

namespace cosim {

ContactMonitor::ContactMonitor(const mjModel* m, const WorldModel& world, const Scenario& scenario)
    : m_(m), floor_(world.floorGeom()), owner_(m->ngeom, -1) {
  for (std::size_t v = 0; v < world.vehicles().size(); ++v) {
    for (int g : world.vehicles()[v].geoms) owner_[g] = static_cast<int>(v);
    kinds_.push_back(world.vehicles()[v].kind);
    starts_.push_back(scenario.vehicles[v].start);
    goals_.push_back(scenario.vehicles[v].goal());
  }
}

void ContactMonitor::update(const mjData* d, RunLog& log) {
  if (d->ncon == 0 && previous_.empty()) return;
  current_.clear();
  for (int i = 0; i < d->ncon; ++i) {
    const mjContact& c = d->contact[i];
    note(c.geom1, c.geom2, c, d, log);
    note(c.geom2, c.geom1, c, d, log);
  }
  previous_.swap(current_);
}

void ContactMonitor::note(int mine, int other, const mjContact& c, const mjData* d, RunLog& log) {
  const int v = owner_[mine];
  if (v < 0 || owner_[other] == v) return;
  const Eigen::Vector3d p(c.pos[0], c.pos[1], c.pos[2]);
  if (other == floor_ && floorAllowed(v, p)) return;
  const long key = static_cast<long>(v) * m_->ngeom + other;
  if (std::find(current_.begin(), current_.end(), key) != current_.end()) return;
  current_.push_back(key);
  if (std::find(previous_.begin(), previous_.end(), key) == previous_.end()) {
    const char* name = mj_id2name(m_, mjOBJ_GEOM, other);
    log.vehicles[v].collisions.push_back(
        {d->time, name ? name : "geom" + std::to_string(other), p});
  }
}

bool ContactMonitor::floorAllowed(int v, const Eigen::Vector3d& p) const {
  if (kinds_[v] == VehicleKind::GroundRobot) return true;
  const auto nearXY = [&p](const Eigen::Vector3d& spot) {
    return (p - spot).head<2>().norm() < 1.0;
  };
  return nearXY(starts_[v]) || nearXY(goals_[v]);
}

}  // namespace cosim
