#pragma once
// The genetic algorithm that seed 002 (part A) compares its grid ants with. The seed gives only
// its population and iteration counts (population = number of ants; 50~100 iterations) and, for
// its part-B GA, elitist selection, crossover probability 0.6 and mutation probability 0.05.
// The operators follow the grid-path GA that seed 000 reviews (Tuncer and Yildirim, "Dynamic
// path planning of mobile robots with improved genetic algorithm", Computers & Electrical
// Engineering 38 (2012) 1564-1572): a chromosome is a path of cells; initial chromosomes are
// random walks guided by the same heading heuristic as the ants; binary tournament selection;
// one-point crossover at a cell both parents pass through; mutation moves a node to the
// neighbouring cell that shortens the path most while keeping both its moves legal; loops are
// cut; the best chromosome always survives (elitism).
// The seed's part A describes no operators at all. Its plain variant (guided_initial and
// shortening_mutation false) keeps only what any grid-path GA has: initial walks that pick each
// move uniformly at random, and a mutation that moves a node to a random neighbouring cell that
// keeps both its moves legal (the random mutation Tuncer and Yildirim improve on).
#include "planning/grid/grid_planner.h"

namespace cosim {

struct GeneticAlgorithmParams {
  int population = 20;
  int generations = 50;
  double crossover_probability = 0.6;
  double mutation_probability = 0.05;  // per interior node
  int directions = 8;                  // 4, 8, 16, 24 or 32
  bool guided_initial = true;          // initial walks guided by the ants' heuristic (else uniform)
  bool shortening_mutation = true;     // Tuncer-Yildirim mutation (else a random legal neighbour)
  bool local_search = false;           // not in the seed: staircase shortcut on every child
};

class GeneticAlgorithm : public GridPlanner {
 public:
  explicit GeneticAlgorithm(GeneticAlgorithmParams params = {}) : p_(params) {}
  std::string name() const override { return "ga"; }
  GridPlanResult solveGrid(const GridQuery& query, const StopToken& stop) override;

 private:
  GeneticAlgorithmParams p_;
};

}  // namespace cosim
