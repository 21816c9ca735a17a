#include "planning/navigation/navigation_planners.h"

#include <memory>
#include <string>

#include "planning/navigation/d_star_lite.h"
#include "planning/navigation/navigator_grid_planner.h"
#include "planning/navigation/robot_navigation_ant.h"
#include "planning/swarm/msac_saco_planners.h"

namespace cosim {

namespace {
// A NavigatorGridPlanner named `name` whose robot is Navigator(read(params, extra...)).
template <class Navigator, class ReadParams, class... Extra>
GridPlannerFactory navigatorFactory(const std::string& name, ReadParams read, Extra... extra) {
  return [name, read, extra...](ParamSet& params) -> std::unique_ptr<GridPlanner> {
    const auto p = read(params, extra...);
    return std::make_unique<NavigatorGridPlanner>(name,
                                                  [p] { return std::make_unique<Navigator>(p); });
  };
}

ObstaclePrediction readPrediction(ParamSet& params) {
  return params.getString("prediction", "constant_velocity", {"constant_velocity", "trajectory"}) ==
                 "trajectory"
             ? ObstaclePrediction::Trajectory
             : ObstaclePrediction::ConstantVelocity;
}

RnaParams readRnaParams(ParamSet& params, bool wave_front) {
  RnaParams p;
  p.wave_front = wave_front;
  p.sight = params.getInt("sight", p.sight, 1, 1000);
  p.oscillation_any = params.getString("oscillation", "any", {"previous", "any"}) == "any";
  p.max_replans = params.getInt("max_replans", p.max_replans, 0, 1000);
  p.max_waits = params.getInt("max_waits", p.max_waits, 0, 100000);
  p.prediction = readPrediction(params);
  p.conditional_diagonal = readConditionalDiagonal(params);
  if (!wave_front) {
    p.msac.ants = params.getInt("ants", p.msac.ants, 1, 127);
    p.msac.iterations = params.getInt("iterations", p.msac.iterations, 1, 1000);
  }
  return p;
}

DStarLiteParams readDStarLiteParams(ParamSet& params) {
  DStarLiteParams p;
  p.sight = params.getInt("sight", p.sight, 1, 1000);
  p.conditional_diagonal = readConditionalDiagonal(params);
  p.prediction = readPrediction(params);
  return p;
}
}  // namespace

void registerNavigationPlanners(PlannerRegistry& r) {
  for (const bool wave_front : {false, true}) {
    const std::string name = wave_front ? "wf_rna" : "rna";
    r.addGridPlanner(name, "navigation",
                     wave_front
                         ? "RNA with a wave-front local planner: drives through the map "
                           "seen only through its field of view (Pencik 2014)"
                         : "Robot Navigation Ant: drives through the map seen only through "
                           "its field of view, re-planning with MSAC each step (Pencik 2014)",
                     navigatorFactory<RobotNavigationAnt>(name, readRnaParams, wave_front));
  }
  r.addGridPlanner("d_star_lite", "navigation",
                   "D* Lite: incremental replanning while driving through a map seen only "
                   "through the field of view (Koenig & Likhachev 2002)",
                   navigatorFactory<DStarLite>("d_star_lite", readDStarLiteParams));
}

}  // namespace cosim
