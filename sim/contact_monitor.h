#pragma once
// Contact bookkeeping for the simulation loops: counts the onsets of contact between a vehicle and
// anything else (an obstacle, another vehicle, a moving obstacle), except the floor where it is
// not a collision: anywhere under a ground robot (it drives on it), and near a quadrotor's start
// or goal (its landing spots). A contact that lasts many steps is one collision.
#include <mujoco/mujoco.h>

#include <Eigen/Core>
#include <vector>

#include "sim/run_log.h"
#include "sim/scenario.h"
#include "sim/world_model.h"

namespace cosim {

class ContactMonitor {
 public:
  ContactMonitor(const mjModel* m, const WorldModel& world, const Scenario& scenario);

  // Books new contacts into log.vehicles[v].collisions. Cheap when nothing touches: called every
  // physics step.
  void update(const mjData* d, RunLog& log);

 private:
  void note(int mine, int other, const mjContact& c, const mjData* d, RunLog& log);
  bool floorAllowed(int vehicle, const Eigen::Vector3d& p) const;

  const mjModel* m_;
  int floor_;
  std::vector<int> owner_;  // geom -> vehicle index, -1 for the world
  std::vector<VehicleKind> kinds_;
  std::vector<Eigen::Vector3d> starts_, goals_;
  std::vector<long> previous_, current_;  // (vehicle, other geom) pairs in contact
};

}  // namespace cosim
