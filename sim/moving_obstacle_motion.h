#pragma once
// Moving obstacles in the simulation: where a scenario's moving obstacle is at time t (its centre
// travels along its path at constant speed, back and forth or in a loop), and the MuJoCo mocap
// bodies that carry them ("moving<i>", one geom of the same name, standing on the floor).
#include <tinyxml2.h>

#include <Eigen/Core>

#include "sim/scenario.h"

namespace cosim {

// Centre (x, y) at time t >= 0, metres.
Eigen::Vector2d movingObstaclePosition(const MovingObstacleSpec& o, double t);

// Radius of the obstacle's footprint: the cylinder's radius or the box's half diagonal.
double movingObstacleFootprintRadius(const MovingObstacleSpec& o);

// Appends one mocap body per moving obstacle to `worldbody`, at its position at t = 0.
void addMovingObstacleBodies(tinyxml2::XMLDocument& doc, tinyxml2::XMLElement* worldbody,
                             const Scenario& scenario);

// The name of moving obstacle i's body and geom.
std::string movingObstacleName(std::size_t i);

}  // namespace cosim
