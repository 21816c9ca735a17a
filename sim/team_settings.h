#pragma once
// What a scenario's `team:` section asks of a quadrotor team planned jointly: how many times its
// smoothed plan is flown in cosim before it is trusted (run/team_plan_verification.h), and the
// share of its rotors' thrust a member's trajectory may ask for (planning/team/team_thrust.h).
namespace cosim {

struct TeamSettings {
  // Verification flights at most; 0: the plan is flown once, as the run, without being checked.
  int verify_rounds = 4;
  // A member's planned thrust (gravity, its acceleration and the downwash of the members above it
  // counted) never above this fraction of its rotors' maximum: 20 % is kept for control, as a
  // single quadrotor's minimum-snap fit keeps (run/quadrotor_plans.cpp).
  double max_thrust_fraction = 0.8;

  // The keys (sim/declared_keys.h).
  template <class Visitor>
  void declareKeys(Visitor& v) {
    v.integer("verify_rounds", verify_rounds, 0, 20,
              "verification flights of a quadrotor team's plan at most (each repairs what the last "
              "one found); 0: fly the plan unverified");
    v.number("max_thrust_fraction", max_thrust_fraction, 0.3, 1.0,
             "the share of its rotors' maximum thrust a team member's trajectory may ask for, the "
             "downwash of members above counted");
  }
};

}  // namespace cosim
