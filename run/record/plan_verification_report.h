#pragma once
// What the verification flights of a quadrotor team's plan found and changed
// (run/team_plan_verification.h): metrics.json's "plan_verification" and one console line per
// round.
#include <string>
#include <vector>

namespace cosim {

// A pair that came closer in flight than its separation ellipsoid allows (1.0: touching).
struct FlownConflict {
  std::string a, b;         // the vehicles' names
  double t = 0.0;           // s of the flight, where the pair came closest
  double separation = 0.0;  // the flown ellipsoidal distance there
};

struct VerificationRound {
  int round = 0;                         // 1, 2, ...
  double flight_wall_s = 0.0;            // s the headless flight took
  double min_separation = 0.0;           // the closest pair of the flight, ellipsoids
  double peak_thrust_fraction = 0.0;     // the largest rotor thrust over its maximum, any member
  int uav_contacts = 0;                  // pairs that touched
  bool arrived = false;                  // every member reached its goal
  std::vector<FlownConflict> conflicts;  // every pair below 1.0, its closest instant
  std::string repair;                    // what the next plan changes ("" after the last round)
};

struct PlanVerificationReport {
  bool ran = false;      // a team plan was verified (team.verify_rounds > 0)
  bool clean = false;    // the last flight kept every pair apart and all arrived
  double seconds = 0.0;  // wall time of every round: flights and re-plans
  std::vector<VerificationRound> rounds;
};

}  // namespace cosim
