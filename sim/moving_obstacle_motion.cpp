#include "sim/moving_obstacle_motion.h"

#include <cmath>

#include "core/decimal_text.h"

namespace cosim {

Eigen::Vector2d movingObstaclePosition(const MovingObstacleSpec& o, double t) {
  if (o.path.size() < 2 || !(o.speed > 0)) return o.path.front();
  // The closed route: the path there and back (back and forth) or back to its start (loop).
  std::vector<Eigen::Vector2d> route = o.path;
  if (o.loop)
    route.push_back(o.path.front());
  else
    route.insert(route.end(), o.path.rbegin() + 1, o.path.rend());
  double total = 0.0;
  for (std::size_t i = 1; i < route.size(); ++i) total += (route[i] - route[i - 1]).norm();
  if (!(total > 0)) return o.path.front();
  double s = std::fmod(std::max(0.0, t) * o.speed, total);
  for (std::size_t i = 1; i < route.size(); ++i) {
    const double len = (route[i] - route[i - 1]).norm();
    if (s <= len && len > 0) return route[i - 1] + (s / len) * (route[i] - route[i - 1]);
    s -= len;
  }
  return route.back();
}

double movingObstacleFootprintRadius(const MovingObstacleSpec& o) {
  return o.type == ObstacleType::Box ? 0.5 * o.size.head<2>().norm() : o.radius;
}

std::string movingObstacleName(std::size_t i) {
  return "moving" + std::to_string(i);
}

void addMovingObstacleBodies(tinyxml2::XMLDocument& doc, tinyxml2::XMLElement* worldbody,
                             const Scenario& s) {
  // 1 mm above the floor: resting on it would make a floor contact every step for nothing.
  const double lift = 0.001;
  for (std::size_t i = 0; i < s.moving_obstacles.size(); ++i) {
    const MovingObstacleSpec& o = s.moving_obstacles[i];
    const Eigen::Vector2d p = movingObstaclePosition(o, 0.0);
    tinyxml2::XMLElement* body = doc.NewElement("body");
    worldbody->InsertEndChild(body);
    body->SetAttribute("name", movingObstacleName(i).c_str());
    body->SetAttribute("mocap", "true");
    const double z = s.world.bounds_min.z() + lift + 0.5 * o.height;
    body->SetAttribute("pos", (tenSignificantDigits(p.x()) + " " + tenSignificantDigits(p.y()) +
                               " " + tenSignificantDigits(z))
                                  .c_str());
    tinyxml2::XMLElement* g = doc.NewElement("geom");
    body->InsertEndChild(g);
    g->SetAttribute("name", movingObstacleName(i).c_str());
    g->SetAttribute("rgba", "0.85 0.2 0.25 1");
    if (o.type == ObstacleType::Box) {
      g->SetAttribute("type", "box");
      g->SetAttribute("size", (tenSignificantDigits(0.5 * o.size.x()) + " " +
                               tenSignificantDigits(0.5 * o.size.y()) + " " +
                               tenSignificantDigits(0.5 * o.height))
                                  .c_str());
    } else {
      g->SetAttribute("type", "cylinder");
      g->SetAttribute(
          "size",
          (tenSignificantDigits(o.radius) + " " + tenSignificantDigits(0.5 * o.height)).c_str());
    }
  }
}

}  // namespace cosim
