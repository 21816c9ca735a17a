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
#include "planning/grid/grid_planner.h"

namespace cosim {

struct GeneticAlgorithmParams {
  int population = 20;
  int generations = 50;
  double crossover_probability = 0.6;
  double mutation_probability = 0.05;  // per interior node
  int directions = 8;                  // 4, 8, 16, 24 or 32
  bool local_search = false;           // not in the seed: staircase shortcut on every child
};

class GeneticAlgorithm : public GridPlanner {
 public:
  explicit GeneticAlgorithm(GeneticAlgorithmParams params = {}) : p_(params) {}
  std::string name() const override { return "ga"; }
  GridPlanResult solveGrid(const GridQuery& query) override;

 private:
  GeneticAlgorithmParams p_;
};

}  // namespace cosim
