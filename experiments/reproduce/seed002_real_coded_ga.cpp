#include "experiments/reproduce/seed002_real_coded_ga.h"

#include <algorithm>
#include <limits>
#include <random>

#include "core/stop_token.h"

namespace cosim::reproduce {

int convergedAt(const std::vector<double>& history) {
  if (history.empty()) return 0;
  for (std::size_t i = 0; i < history.size(); ++i)
    if (history[i] <= history.back() * (1 + kConverged)) return static_cast<int>(i) + 1;
  return static_cast<int>(history.size());
}

GaRun realCodedGa(const Seed002MaklinkMap& map, const std::vector<int>& lines, std::uint64_t seed,
                  int generations) {
  const MaklinkGraph& g = map.graph;
  const StopToken clock(60.0);
  const int d = static_cast<int>(lines.size());
  const int population = 50;
  const double pc = 0.6, pm = 0.05;
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  auto length = [&](const std::vector<double>& h) {
    Eigen::Vector2d prev = map.start;
    double total = 0.0;
    for (int i = 0; i <= d; ++i) {
      const Eigen::Vector2d p = i < d ? g.lines()[lines[i]].at(h[i]) : map.goal;
      if (!g.segmentFree(prev, p)) return std::numeric_limits<double>::infinity();
      total += (p - prev).norm();
      prev = p;
    }
    return total;
  };
  std::vector<std::vector<double>> pop(population, std::vector<double>(d));
  std::vector<double> fit(population);
  for (auto& x : pop)
    for (double& h : x) h = unit(rng);
  for (int k = 0; k < population; ++k) fit[k] = length(pop[k]);
  GaRun run;
  double best = std::numeric_limits<double>::infinity();
  std::vector<double> best_h;
  std::vector<double> history;
  std::uniform_int_distribution<int> pick(0, population - 1);
  for (int gen = 1; gen <= generations; ++gen) {
    const int elite = static_cast<int>(std::min_element(fit.begin(), fit.end()) - fit.begin());
    if (fit[elite] < best) best = fit[elite], best_h = pop[elite];
    if (gen > 1) history.push_back(best);  // best after generation gen - 1
    std::vector<std::vector<double>> next = {pop[elite]};
    auto tournament = [&]() -> const std::vector<double>& {
      const int a = pick(rng), b = pick(rng);
      return fit[a] <= fit[b] ? pop[a] : pop[b];
    };
    while (static_cast<int>(next.size()) < population) {
      std::vector<double> a = tournament(), b = tournament();
      if (unit(rng) < pc) {
        const double l = unit(rng);
        for (int i = 0; i < d; ++i) {
          const double ai = a[i], bi = b[i];
          a[i] = l * ai + (1 - l) * bi;
          b[i] = l * bi + (1 - l) * ai;
        }
      }
      for (auto* c : {&a, &b}) {
        for (double& h : *c)
          if (unit(rng) < pm) h = unit(rng);
        if (static_cast<int>(next.size()) < population) next.push_back(*c);
      }
    }
    pop.swap(next);
    for (int k = 0; k < population; ++k) fit[k] = length(pop[k]);
    run.generations = gen;
  }
  const int last = static_cast<int>(std::min_element(fit.begin(), fit.end()) - fit.begin());
  if (fit[last] < best) best = fit[last], best_h = pop[last];
  history.push_back(best);
  run.offsets = best_h;
  run.converged_at = convergedAt(history);
  run.length = best;
  run.time_ms = clock.elapsedMs();
  return run;
}

}  // namespace cosim::reproduce
