#include "run/team_plan_verification.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "core/input_error.h"
#include "planning/team/separation_ellipsoid.h"
#include "run/prepared_run.h"
#include "run/quadrotor_plans.h"
#include "run/run_pilots.h"
#include "sim/simulation_loop.h"

namespace cosim {

namespace {

constexpr double kTouching = 1.0;  // ellipsoidal distance of a pair on its ellipsoid's surface
// A repair widens the team's separation by what the flight lacked and this much more, at least
// this much (ellipsoids).
constexpr double kWidenReserve = 0.1;
constexpr double kMinWiden = 0.15;
// The separation is never widened beyond this share of the closest pair of starts (or goals):
// the dense roadmap must hold them (planning/team/dense_roadmap.h).
constexpr double kStartShare = 0.98;
// Each slowing stretches the step time by this factor.
constexpr double kSlowStretch = 1.3;
// A pair rests at this many waypoints before the step of its conflict and after it.
constexpr long kRestBefore = 1, kRestAfter = 2;

std::string fixed(double v, int digits) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.*f", digits, v);
  return buf;
}

struct TeamView {
  std::vector<std::size_t> vehicles;  // log / world indices of the team's members
  std::vector<SeparationEllipsoid> ellipsoids;
  std::vector<double> max_thrust;  // per rotor, N
};

TeamView teamView(const PreparedRun& run) {
  TeamView v;
  v.vehicles = run.setup.quadrotors;
  for (std::size_t w : v.vehicles) {
    const QuadrotorParams& q = run.world.vehicles()[w].params;
    v.ellipsoids.push_back({q.separation_radius, q.separation_height});
    v.max_thrust.push_back(q.max_thrust);
  }
  return v;
}

// What one flight shows: every pair's closest instant below touching, contacts, arrivals, thrust.
VerificationRound inspectFlight(const RunLog& log, const TeamView& team,
                                std::map<std::pair<std::size_t, std::size_t>, double>& at) {
  VerificationRound r;
  r.min_separation = std::numeric_limits<double>::infinity();
  r.arrived = log.end_reason == RunEnd::Goal;
  const std::size_t n = team.vehicles.size();
  std::map<std::pair<std::size_t, std::size_t>, FlownConflict> worst;
  for (std::size_t a = 0; a < n; ++a) {
    const VehicleLog& va = log.vehicles[team.vehicles[a]];
    r.arrived = r.arrived && va.reached_goal;
    for (const LogSample& s : va.samples)
      for (int k = 0; k < 4; ++k)
        r.peak_thrust_fraction =
            std::max(r.peak_thrust_fraction, s.rotor_thrust[k] / team.max_thrust[a]);
    for (std::size_t b = a + 1; b < n; ++b) {
      const VehicleLog& vb = log.vehicles[team.vehicles[b]];
      const SeparationEllipsoid e =
          SeparationEllipsoid::between(team.ellipsoids[a], team.ellipsoids[b]);
      const std::size_t m = std::min(va.samples.size(), vb.samples.size());
      for (std::size_t k = 0; k < m; ++k) {
        const double d = e.distance(va.samples[k].pos, vb.samples[k].pos);
        r.min_separation = std::min(r.min_separation, d);
        if (d >= kTouching) continue;
        FlownConflict& c = worst[{a, b}];
        if (c.a.empty() || d < c.separation) c = {va.name, vb.name, va.samples[k].t, d};
      }
    }
  }
  for (const auto& [pair, c] : worst) {
    r.conflicts.push_back(c);
    at[pair] = c.t;
  }
  // Contacts between two members (each booked by both: counted once, sim/contact_monitor.h).
  for (std::size_t a = 0; a < n; ++a)
    for (const ContactEvent& c : log.vehicles[team.vehicles[a]].collisions)
      for (std::size_t b = a + 1; b < n; ++b)
        if (c.other.rfind(log.vehicles[team.vehicles[b]].name + "/", 0) == 0) ++r.uav_contacts;
  return r;
}

// The smallest ellipsoidal distance between two starts or two goals of the team: the separation
// the roadmap can hold at most.
double startSpacing(const PreparedRun& run, const TeamView& team) {
  double spacing = std::numeric_limits<double>::infinity();
  for (std::size_t a = 0; a < team.vehicles.size(); ++a)
    for (std::size_t b = a + 1; b < team.vehicles.size(); ++b) {
      const VehicleSpec& va = run.scenario.vehicles[team.vehicles[a]];
      const VehicleSpec& vb = run.scenario.vehicles[team.vehicles[b]];
      const SeparationEllipsoid e =
          SeparationEllipsoid::between(team.ellipsoids[a], team.ellipsoids[b]);
      spacing =
          std::min({spacing, e.distance(va.start, vb.start), e.distance(va.goal(), vb.goal())});
    }
  return spacing;
}

double counter(const RunPlan& plan, const char* name) {
  const auto& c = plan.quadrotors.summary.counters;
  const auto it = c.find(name);
  return it == c.end() ? 0.0 : it->second;
}

// The next plan's repairs for the conflicts of this flight (see the header); what they change.
// A flown conflict is a tracking shortfall (the smoothing kept every pair min_separation apart on
// paper): widening the separation by what the flight lacked covers it wherever it came from (a
// wake from above, saturation), so that comes first while the starts and goals allow it; then the
// pairs rest around their conflicts; then the team slows.
std::string repairFor(const VerificationRound& r,
                      const std::map<std::pair<std::size_t, std::size_t>, double>& at,
                      double planned, double step, double max_separation, TeamRepairs& repairs) {
  const double kept = std::max(repairs.min_separation, std::min(planned, max_separation));
  const double widened = std::min(
      max_separation, kept + std::max(kMinWiden, kTouching - r.min_separation + kWidenReserve));
  if (widened > kept + 1e-6) {
    repairs.min_separation = widened;
    for (auto& steps : repairs.rest_steps) steps.clear();  // a new roadmap: its own waypoints
    return "the team's separation widened from " + fixed(kept, 2) + " to " + fixed(widened, 2) +
           " ellipsoids (planned again)";
  }
  std::set<std::size_t> rested;
  for (const auto& [pair, t] : at) {
    const long k = static_cast<long>(std::floor(t / step));
    for (const std::size_t m : {pair.first, pair.second})
      for (long s = k - kRestBefore; s <= k + kRestAfter; ++s) {
        auto& steps = repairs.rest_steps[m];
        if (s < 0 || std::find(steps.begin(), steps.end(), s) != steps.end()) continue;
        steps.push_back(s);
        rested.insert(m);
      }
  }
  if (!rested.empty())
    return std::to_string(rested.size()) +
           " members rest at the waypoints around their conflicts (separation at its largest, " +
           fixed(kept, 2) + " ellipsoids)";
  repairs.step_stretch *= kSlowStretch;
  return "the team slowed: step time x" + fixed(repairs.step_stretch, 2);
}

std::string roundLine(const VerificationRound& r) {
  std::string line = "plan verification round " + std::to_string(r.round) + ": ";
  if (r.conflicts.empty())
    line += "every pair apart";
  else {
    line += std::to_string(r.conflicts.size()) + " pair(s) inside their ellipsoid (";
    for (std::size_t k = 0; k < std::min<std::size_t>(3, r.conflicts.size()); ++k)
      line += (k ? ", " : "") + r.conflicts[k].a + "/" + r.conflicts[k].b + " at " +
              fixed(r.conflicts[k].t, 2) + " s: " + fixed(r.conflicts[k].separation, 2);
    line += r.conflicts.size() > 3 ? ", ...)" : ")";
  }
  line += ", closest " + fixed(r.min_separation, 2) + ", " + std::to_string(r.uav_contacts) +
          " contacts, " + (r.arrived ? "all arrived" : "not all arrived") + ", peak thrust " +
          fixed(r.peak_thrust_fraction, 2) + "; flown in " + fixed(r.flight_wall_s, 1) + " s";
  if (!r.repair.empty()) line += "; repair: " + r.repair;
  return line;
}

std::string conflictList(const VerificationRound& r) {
  std::string out;
  for (const FlownConflict& c : r.conflicts)
    out += (out.empty() ? "" : ", ") + c.a + "/" + c.b + " at " + fixed(c.t, 2) + " s (" +
           fixed(c.separation, 2) + " ellipsoids)";
  return out;
}

// Plans the team again with `repairs` and rebuilds the pilots; false (with the run's plan failed)
// when no plan was found.
bool replan(PreparedRun& run, const TeamRepairs& repairs) {
  run.plan.quadrotors =
      planQuadrotors(run.scenario, run.setup.quadrotor_sections, run.world, run.setup.quadrotors,
                     run.setup.quadrotor_planning, run.request, run.report, repairs);
  if (run.plan.quadrotors.status != PlanStatus::Ready) {
    run.plan.status = run.plan.quadrotors.status;
    run.plan.message = run.plan.quadrotors.failure;
    return false;
  }
  run.pilots = buildPilots(run.scenario, run.setup, run.world, run.plan);
  return true;
}

}  // namespace

bool verifiesTeamPlan(const PreparedRun& run) {
  return run.scenario.team.verify_rounds > 0 && run.setup.robots.empty() &&
         run.setup.quadrotor_planning == Planning::Team && run.setup.quadrotors.size() > 1 &&
         run.plan.drivable();
}

std::optional<RunLog> verifyTeamPlan(PreparedRun& run, PlanVerificationReport& report) {
  const auto start = std::chrono::steady_clock::now();
  const TeamView team = teamView(run);
  double max_separation = kStartShare * startSpacing(run, team);
  TeamRepairs repairs;
  repairs.rest_steps.resize(team.vehicles.size());
  SimulationOptions options = run.loop;
  options.profile = nullptr;  // the run's profile is its own flight's
  report.ran = true;
  std::optional<RunLog> flight;
  for (int round = 1; round <= run.scenario.team.verify_rounds; ++round) {
    const auto flight_start = std::chrono::steady_clock::now();
    flight.reset();  // one flight's log at a time (500 vehicles' take gigabytes)
    SimulationLoop loop(run.world, run.scenario, run.pilots.robots, run.pilots.quadrotors, options);
    while (loop.stepControl()) {
    }
    flight = loop.finish();
    if (flight->end_reason == RunEnd::Interrupted) {
      run.stopped = true;
      return std::nullopt;
    }
    std::map<std::pair<std::size_t, std::size_t>, double> at;
    VerificationRound r = inspectFlight(*flight, team, at);
    r.round = round;
    r.flight_wall_s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - flight_start).count();
    report.clean = r.conflicts.empty() && r.uav_contacts == 0 && r.arrived;
    const bool last = report.clean || round == run.scenario.team.verify_rounds || at.empty();
    bool planned = true;
    if (!last) {
      // What the flown plan kept: the repair is planned from it.
      const double planned_separation = counter(run.plan, "planned_min_separation");
      const double step = counter(run.plan, "step_duration_s");
      const PlanStatus status = run.plan.status;
      const std::string message = run.plan.message;
      const TeamRepairs before = repairs;
      r.repair = repairFor(r, at, planned_separation, step, max_separation, repairs);
      try {
        planned = replan(run, repairs);
      } catch (const InputError&) {
        planned = false;
      }
      if (!planned && repairs.min_separation != before.min_separation) {
        // No plan at the widened separation (no roadmap holds these starts and goals at it, or
        // the search found none): widen no further, and repair the pairs where they broke.
        run.plan.status = status;
        run.plan.message = message;
        repairs = before;
        max_separation = std::max(repairs.min_separation, planned_separation);
        r.repair = repairFor(r, at, planned_separation, step, max_separation, repairs);
        planned = replan(run, repairs);
      }
    }
    run.report.message(roundLine(r));
    report.rounds.push_back(r);
    if (last) break;
    if (!planned) {
      flight.reset();
      break;
    }
  }
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!report.clean && run.plan.drivable()) {
    const VerificationRound& r = report.rounds.back();
    run.plan.status = PlanStatus::Conflicting;
    run.plan.message =
        "the team's plan still breaks in flight after " + std::to_string(report.rounds.size()) +
        " verification round(s) (team.verify_rounds): " +
        (r.conflicts.empty()
             ? std::string(r.arrived ? "members touched" : "not every member reached its goal")
             : conflictList(r));
  }
  return flight;
}

}  // namespace cosim
