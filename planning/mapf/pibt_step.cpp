#include "planning/mapf/pibt_step.h"

#include <algorithm>

namespace cosim {

PibtStep::PibtStep(const MapfGraph& graph, const GoalDistanceTable& distance,
                   std::span<const int> goals, bool swap)
    : graph_(graph),
      distance_(distance),
      goals_(goals),
      swap_(swap),
      stride_(graph.maxDegree() + 1),
      now_(goals.size(), kNone),
      next_(goals.size(), kNone),
      occupant_now_(graph.vertexCount(), kNone),
      occupant_next_(graph.vertexCount(), kNone),
      key_owner_(graph.moveKeyCount(), kNone),
      candidates_(goals.size() * static_cast<std::size_t>(stride_)) {}

bool PibtStep::next(std::span<const int> from, std::span<const int> order,
                    std::span<const FixedMove> fixed, SplitMix64& rng, std::span<int> to) {
  const int n = static_cast<int>(from.size());
  for (int i = 0; i < n; ++i) {
    now_[i] = from[i];
    next_[i] = kNone;
    occupant_now_[from[i]] = i;
  }
  bool ok = true;
  for (const FixedMove& m : fixed)
    if (!(ok = placeFixed(m))) break;
  for (std::size_t k = 0; ok && k < order.size(); ++k)
    if (next_[order[k]] == kNone) ok = push(order[k], rng);
  if (ok)
    for (int i = 0; i < n; ++i) to[i] = next_[i];
  clear();
  return ok;
}

void PibtStep::clear() {
  for (const int v : now_) occupant_now_[v] = kNone;
  for (const int v : touched_vertices_) occupant_next_[v] = kNone;
  for (const std::uint32_t k : touched_keys_) key_owner_[k] = kNone;
  touched_vertices_.clear();
  touched_keys_.clear();
}

std::uint32_t PibtStep::keyOf(int from, int to) const {
  if (from == to) return kStay;
  const auto targets = graph_.neighbours(from);
  const auto keys = graph_.moveKeys(from);
  for (std::size_t k = 0; k < targets.size(); ++k)
    if (targets[k] == to) return keys[k];
  return kStay;  // not a move of the graph; callers pass only neighbours
}

void PibtStep::reserveKey(std::uint32_t key, int agent) {
  if (key == kStay) return;
  key_owner_[key] = agent;
  touched_keys_.push_back(key);
}

bool PibtStep::placeFixed(const FixedMove& m) {
  if (occupant_next_[m.vertex] != kNone || next_[m.agent] != kNone) return false;
  const std::uint32_t key = keyOf(now_[m.agent], m.vertex);
  if (key != kStay && key_owner_[key] != kNone) return false;  // a swap or crossing
  reserveKey(key, m.agent);
  next_[m.agent] = m.vertex;
  occupant_next_[m.vertex] = m.agent;
  touched_vertices_.push_back(m.vertex);
  return true;
}

void PibtStep::sortCandidates(int agent, SplitMix64& rng) {
  const int v = now_[agent];
  Candidate* c = candidates_.data() + static_cast<std::size_t>(agent) * stride_;
  const auto targets = graph_.neighbours(v);
  const auto keys = graph_.moveKeys(v);
  const int count = static_cast<int>(targets.size()) + 1;
  for (std::size_t k = 0; k < targets.size(); ++k)
    c[k] = {targets[k], keys[k], distance_(agent, targets[k]), rng.unit()};
  c[count - 1] = {v, kStay, distance_(agent, v), rng.unit()};
  // Nearest the goal first, ties at random (AIJ 2022 Alg. 1 line 2). Insertion sort: at most 27.
  for (int i = 1; i < count; ++i) {
    const Candidate x = c[i];
    int j = i - 1;
    while (j >= 0 &&
           (c[j].distance > x.distance || (c[j].distance == x.distance && c[j].tie > x.tie))) {
      c[j + 1] = c[j];
      --j;
    }
    c[j + 1] = x;
  }
}

bool PibtStep::push(int agent, SplitMix64& rng) {
  const int v = now_[agent];
  sortCandidates(agent, rng);
  Candidate* c = candidates_.data() + static_cast<std::size_t>(agent) * stride_;
  const int count = graph_.degree(v) + 1;
  const int partner = swap_ ? swapPartner(agent) : kNone;
  // A required swap: move away from the goal first, then pull the partner in behind.
  if (partner != kNone) std::reverse(c, c + count);

  for (int k = 0; k < count; ++k) {
    const Candidate u = c[k];
    if (occupant_next_[u.vertex] != kNone) continue;             // vertex conflict
    if (u.key != kStay && key_owner_[u.key] != kNone) continue;  // swap or crossing conflict
    occupant_next_[u.vertex] = agent;
    touched_vertices_.push_back(u.vertex);
    next_[agent] = u.vertex;
    reserveKey(u.key, agent);
    // Priority inheritance: the undecided agent standing there must move out first.
    const int occupant = occupant_now_[u.vertex];
    if (occupant != kNone && occupant != agent && next_[occupant] == kNone &&
        !push(occupant, rng)) {
      // It stays (and now holds u.vertex for the next step); free the move's key, try the next.
      if (u.key != kStay) key_owner_[u.key] = kNone;
      continue;
    }
    if (k == 0 && partner != kNone && next_[partner] == kNone && occupant_next_[v] == kNone) {
      const std::uint32_t key = keyOf(now_[partner], v);
      if (key == kStay || key_owner_[key] == kNone) {
        next_[partner] = v;
        occupant_next_[v] = partner;
        touched_vertices_.push_back(v);
        reserveKey(key, partner);
      }
    }
    return true;
  }
  // No candidate: stay, and report the failure to the agent that pushed (backtracking).
  occupant_next_[v] = agent;
  touched_vertices_.push_back(v);
  next_[agent] = v;
  return false;
}

int PibtStep::roomAround(int v, int exclude, int& last) const {
  int room = 0;
  for (const int u : graph_.neighbours(v)) {
    const int a = occupant_now_[u];
    if (u == exclude || (graph_.degree(u) == 1 && a != kNone && goals_[a] == u)) continue;
    ++room;
    last = u;
  }
  return room;
}

int PibtStep::swapPartner(int agent) const {
  const Candidate* c = candidates_.data() + static_cast<std::size_t>(agent) * stride_;
  const int v = now_[agent], best = c[0].vertex;
  if (best == v) return kNone;  // it wants to stay
  // Head-on: the agent on the best vertex would be pushed back along a corridor.
  const int ahead = occupant_now_[best];
  if (ahead != kNone && next_[ahead] == kNone && swapRequired(agent, ahead, v, best) &&
      swapPossible(best, v))
    return ahead;
  // Clearing the way: an agent beside would push this one back through the best vertex.
  for (const int u : graph_.neighbours(v)) {
    const int beside = occupant_now_[u];
    if (beside == kNone || u == best) continue;
    if (swapRequired(beside, agent, v, best) && swapPossible(best, v)) return beside;
  }
  return kNone;
}

bool PibtStep::swapRequired(int pusher, int puller, int v_pusher, int v_puller) const {
  // Walk the corridor the puller would be pushed along while that brings the pusher nearer its
  // goal; a vertex with room for two ways out lets them pass without a swap.
  for (int steps = 0;
       steps < graph_.vertexCount() && distance_(pusher, v_puller) < distance_(pusher, v_pusher);
       ++steps) {
    int last = kNone;
    const int room = roomAround(v_puller, v_pusher, last);
    if (room >= 2) return false;
    if (room == 0) break;
    v_pusher = v_puller;
    v_puller = last;
  }
  return distance_(puller, v_pusher) < distance_(puller, v_puller) &&
         (distance_(pusher, v_pusher) == 0 ||
          distance_(pusher, v_puller) < distance_(pusher, v_pusher));
}

bool PibtStep::swapPossible(int v_pusher, int v_puller) const {
  // Walk on from the puller's side until there is room for the two to exchange places.
  const int origin = v_pusher;
  for (int steps = 0; steps < graph_.vertexCount() && v_puller != origin; ++steps) {
    int last = kNone;
    const int room = roomAround(v_puller, v_pusher, last);
    if (room >= 2) return true;
    if (room == 0) return false;
    v_pusher = v_puller;
    v_puller = last;
  }
  return false;
}

}  // namespace cosim
