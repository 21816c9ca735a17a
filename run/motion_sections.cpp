#include "run/motion_sections.h"

namespace cosim {

MotionSections topLevelSections(const Scenario& s) {
  MotionSections m;
  m.planner = {s.planner_name, s.planner_params, s.planner_margin, s.planner_separation};
  m.trajectory = {s.trajectory_mode, s.trajectory_params};
  m.controller = {s.controller_name, s.controller_drag_compensation, s.controller_gains,
                  s.controller_thrust_path};
  return m;
}

MotionSections aerialSections(const Scenario& s) {
  const AerialSections& a = s.aerial;
  MotionSections m;
  m.planner = {a.planner_name, a.planner_params, a.planner_margin, a.planner_separation};
  m.trajectory = {a.trajectory_mode, a.trajectory_params};
  m.controller = {a.controller_name, a.controller_drag_compensation, a.controller_gains,
                  a.controller_thrust_path};
  return m;
}

}  // namespace cosim
