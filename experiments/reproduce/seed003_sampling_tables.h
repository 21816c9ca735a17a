#pragma once
// Seed 003's continuous-space result tables (Navratil 2019, sec. 4.1.2, Tables 4-17), as
// published: per table the map, mode, N, step, rewire radius, the four RRT*FN caps and the mean
// length and time of RRT, RRT* and RRT*FN at each cap.
namespace cosim::reproduce {

// One table of the thesis: a map, a mode, N, step, rewire radius, four RRT*FN caps, and the
// published mean length [m] and time [s] for RRT, RRT*, FN cap 1..4 (in that order).
struct Seed003SamplingTable {
  const char* label;  // e.g. "Tab. 6"
  const char* map;    // Seed003Map::name
  const char* set;    // "mode 1" or "set 1".."set 4"
  int mode, max_nodes;
  double step, radius;
  int caps[4];
  double length[6];
  double time_s[6];
};

// Values copied from the thesis (summary section 3.4); times are MATLAB seconds on an i5-9600K.
extern const Seed003SamplingTable kSeed003SamplingTables[14];

}  // namespace cosim::reproduce
