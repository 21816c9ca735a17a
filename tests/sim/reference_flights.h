#pragma once
// For simulation tests: references other than a fixed set-point (a straight line at a cruise
// speed), and a flight of every vehicle of a scenario, each along its own reference, under
// controllers one factory builds.
#include <memory>
#include <vector>

#include "control/reference_source.h"
#include "sim/flight_simulation.h"
#include "sim/world_model.h"

namespace cosim::test {

// From `from` to `to`: accelerates at `accel` to `speed`, cruises, brakes and holds at `to`
// (trapezoidal speed; jerk is not limited, which the tests do not need).
class StraightLineReference : public ReferenceSource {
 public:
  StraightLineReference(const Eigen::Vector3d& from, const Eigen::Vector3d& to, double speed,
                        double accel)
      : from_(from),
        dir_((to - from).normalized()),
        length_((to - from).norm()),
        v_(speed),
        a_(accel) {
    t_ramp_ = v_ / a_;
    const double ramp_len = 0.5 * a_ * t_ramp_ * t_ramp_;
    t_cruise_ = (length_ - 2.0 * ramp_len) / v_;  // the tests keep this positive
  }
  FlatReference reference(double t, const VehicleState&) override {
    double s = 0.0, v = 0.0, a = 0.0;
    const double t_brake = t_ramp_ + t_cruise_, t_end = t_brake + t_ramp_;
    if (t < t_ramp_) {
      s = 0.5 * a_ * t * t, v = a_ * t, a = a_;
    } else if (t < t_brake) {
      s = 0.5 * a_ * t_ramp_ * t_ramp_ + v_ * (t - t_ramp_), v = v_;
    } else if (t < t_end) {
      const double u = t_end - t;
      s = length_ - 0.5 * a_ * u * u, v = a_ * u, a = -a_;
    } else {
      s = length_;
    }
    finished_ = t >= t_end;
    FlatReference ref;
    ref.position = from_ + s * dir_;
    ref.velocity = v * dir_;
    ref.acceleration = a * dir_;
    return ref;
  }
  bool atFinalSetpoint() const override { return finished_; }
  // When the cruise at full speed begins and ends.
  double cruiseStart() const { return t_ramp_; }
  double cruiseEnd() const { return t_ramp_ + t_cruise_; }

 private:
  Eigen::Vector3d from_, dir_;
  double length_, v_, a_, t_ramp_, t_cruise_;
  bool finished_ = false;
};

// Flies vehicle i of `s` along *references[i] for the whole sim.max_time, under controllers
// `make(params)` builds from each model's parameters.
template <class MakeController>
RunLog flyAlong(const Scenario& s, const std::vector<ReferenceSource*>& references,
                MakeController make) {
  const WorldModel world = WorldModel::build(s);
  std::vector<std::unique_ptr<FlightController>> controllers;
  std::vector<VehiclePilot> pilots(s.vehicles.size());
  for (std::size_t i = 0; i < s.vehicles.size(); ++i) {
    controllers.push_back(make(world.vehicles()[i].params));
    pilots[i].controller = controllers.back().get();
    pilots[i].reference = references[i];
    pilots[i].goal = s.vehicles[i].goal();
  }
  FlightOptions options;
  options.settings = s.sim;
  options.hold_after_arrival = 1e9;
  return simulateFlight(world, s, pilots, options);
}

}  // namespace cosim::test
