#pragma once
#include "experiments/bench/bench_section.h"

namespace cosim::bench {

// Teams of 10, 100 and 1000 agents (half omni robots on the floor, half cf2 above them): the
// full simulation loop against the bare engine on the same world, and against the bare engine
// on the same world composed with MuJoCo actuators for the rotors and drive servos (as cosim
// composed it before the rotors' and servos' forces went straight into the vehicles' dofs), with
// the process's peak memory; the loop also with its second thread (sim/simulation_loop.h), and
// for 100 agents and more a table of where a physics step goes (loop_profile_table.h).
Section benchTeamScale(bool quick);

}  // namespace cosim::bench
