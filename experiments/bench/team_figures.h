#pragma once
#include "experiments/bench/bench_section.h"

namespace cosim::bench {

// The figure stage (figures/error, top and side, PNG and SVG, render/figures.h) of swarm500's
// 500 Crazyflies against swarm32's 32 and a single vehicle's, each flying the synthetic 20 s log
// of render benchmarks (syntheticTeamLog): seconds per figure set and the 500-vehicle set's ratio
// to the single vehicle's (target: swarm500's figures within 5 s of its flight's end).
Section benchTeamFigures(bool quick);

}  // namespace cosim::bench
