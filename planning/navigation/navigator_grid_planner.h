#pragma once
// A navigator used as a grid planner (`cosim grid-bench`, `cosim plan`): the robot drives from
// start to goal on the query's static grid, knowing only what its field of view has shown it;
// the result is the executed cell path (with any detours it really drove), so its length
// measures the cost of not knowing the map. On a 3D grid it navigates the start's layer (start
// and goal must share it).
#include <functional>
#include <memory>

#include "planning/grid/grid_planner.h"
#include "planning/navigation/navigator.h"

namespace cosim {

class NavigatorGridPlanner : public GridPlanner {
 public:
  using Factory = std::function<std::unique_ptr<Navigator>()>;
  NavigatorGridPlanner(std::string name, Factory make)
      : name_(std::move(name)), make_(std::move(make)) {}
  std::string name() const override { return name_; }
  // Counters: steps, waits, replans, mean_plan_ms, max_plan_ms.
  GridPlanResult solveGrid(const GridQuery& query, const StopToken& stop) override;

 private:
  std::string name_;
  Factory make_;
};

}  // namespace cosim
