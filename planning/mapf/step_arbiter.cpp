#include "planning/mapf/step_arbiter.h"

#include <algorithm>

namespace cosim {

StepArbiter::StepArbiter(const MapfGrid& grid, const std::vector<int>& positions)
    : grid_(&grid),
      position_(positions),
      next_(positions.size(), -1),
      occupant_(grid.cellCount(), -1),
      claimant_(grid.cellCount(), -1),
      move_stamp_(static_cast<std::size_t>(grid.cellCount()) * 4, -1) {
  for (std::size_t i = 0; i < positions.size(); ++i) {
    occupant_[positions[i]] = static_cast<int>(i);
    history_.push_back({positions[i]});
  }
}

void StepArbiter::beginStep() {
  ++step_;
  std::fill(next_.begin(), next_.end(), -1);
  for (const int c : claimed_cells_) claimant_[c] = -1;
  claimed_cells_.clear();
}

bool StepArbiter::tryMove(int agent, int to) {
  if (next_[agent] != -1) return false;  // already decided this step
  const int from = position_[agent];
  if (to != from) {
    const auto n = grid_->neighbours(from);
    if (std::find(n.begin(), n.end(), to) == n.end()) return false;
    const int there = occupant_[to];
    // The occupant must already have decided to leave (it waits if it never decides).
    if (there != -1 && (next_[there] == -1 || next_[there] == to)) return false;
    if (move_stamp_[grid_->moveKey(from, to)] == step_) return false;  // swap or crossing
  }
  if (claimant_[to] != -1) return false;
  next_[agent] = to;
  claimant_[to] = agent;
  claimed_cells_.push_back(to);
  if (to != from) move_stamp_[grid_->moveKey(from, to)] = step_;
  return true;
}

int StepArbiter::commitStep() {
  int moved = 0;
  for (std::size_t a = 0; a < position_.size(); ++a)
    if (next_[a] != -1 && next_[a] != position_[a]) {
      if (occupant_[position_[a]] == static_cast<int>(a)) occupant_[position_[a]] = -1;
      ++moved;
    }
  for (std::size_t a = 0; a < position_.size(); ++a) {
    if (next_[a] != -1) position_[a] = next_[a];
    occupant_[position_[a]] = static_cast<int>(a);
    history_[a].push_back(position_[a]);
  }
  return moved;
}

bool StepArbiter::finished(const std::vector<int>& goals, int max_steps, const StopToken& deadline,
                           MapfResult& result) const {
  if (position_ == goals) {
    result.success = true;
    result.status = searchStatus(true, deadline, PlannerStatus::NoSolution);
    return true;
  }
  const int steps = history_.empty() ? 0 : static_cast<int>(history_[0].size()) - 1;
  if (steps >= max_steps) {
    result.message = "not all agents arrived within " + std::to_string(max_steps) + " steps";
    result.status = searchStatus(false, deadline, PlannerStatus::ApproximateSolution);
  } else if (deadline.expired()) {
    result.message = "time limit reached";
    result.status = expiredStatus(deadline);
  }
  return !result.message.empty();
}

void StepArbiter::storePaths(MapfResult& result) const {
  result.paths.clear();
  for (const auto& cells : history_) {
    MapfPath path = grid_->toCells(cells);
    if (result.success) trimWaitsAtEnd(path);
    result.paths.push_back(std::move(path));
  }
}

}  // namespace cosim
