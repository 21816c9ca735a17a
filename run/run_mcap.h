#pragma once
// A run as an MCAP file (core/mcap_writer.h) for Foxglove and Lichtblick, JSON-encoded messages
// with jsonschema schemas:
//   /world              foxglove.SceneUpdate     the floor and every static shape (t = 0)
//   /vehicles           foxglove.SceneUpdate     each vehicle's shape in its own frame (t = 0)
//   /paths              foxglove.SceneUpdate     planned path, reference and flown path
//                                                 (coloured by error) per vehicle (t = 0)
//   /tf                 foxglove.FrameTransform  world -> <vehicle> at every exported sample
//   /vehicles/<name>/state  cosim.VehicleState   position, reference, estimate, errors, speed,
//                                                 rotor thrusts, for plots
//   /moments            cosim.RunMoment          closest approach, worst error, collisions
#include <cstdint>
#include <string>

#include "run/record/run_record.h"
#include "sim/scenario.h"

namespace cosim {

struct McapExport {
  std::string bytes;  // the file
  std::uint64_t messages = 0;
  int channels = 0;
};

// The record of a run of `scenario` (its world and log). rate: samples per second of /tf and the
// state topics (0: every logged sample). library: the writer named in the file's Header
// ("cosim 0.1.0").
McapExport runToMcap(const Scenario& scenario, const RunRecord& record, double rate,
                     const std::string& library);

}  // namespace cosim
