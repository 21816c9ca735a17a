#pragma once
// The real-coded genetic algorithm seed 002, part B compares its ant colony system with, on the
// MAKLINK example map: one gene per free line Dijkstra's path crosses, the offset h in [0, 1]
// along that line; population 50, crossover 0.6, mutation 0.05, elitist (the seed's settings).
#include <cstdint>
#include <vector>

#include "experiments/reproduce/seed002_maklink_map.h"

namespace cosim::reproduce {

// "Converged": the best so far is within 0.1% of the run's final best (a continuous GA keeps
// making tiny improvements; a strict "last improvement" would measure those instead).
constexpr double kConverged = 1e-3;

// The first iteration (1-based) whose best is within kConverged of history.back().
int convergedAt(const std::vector<double>& history);

// The seed's comparison GA: real-coded offsets h in [0, 1] per crossed line, binary tournament,
// arithmetic crossover (probability pc), uniform mutation per gene (pm), elitism.
struct GaRun {
  std::vector<double> offsets;  // the best individual's h per crossed line
  double length = 0.0;
  int converged_at = 0;  // first generation within kConverged of the final best
  double time_ms = 0.0;
  int generations = 0;
};

GaRun realCodedGa(const Seed002MaklinkMap& map, const std::vector<int>& lines, std::uint64_t seed,
                  int generations);

}  // namespace cosim::reproduce
