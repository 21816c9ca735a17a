#pragma once
// JSON Schemas (jsonschema encoding) of the Foxglove well-known message types a run's MCAP file
// uses, as Foxglove's schema repository defines them (foxglove/schemas, schemas/jsonschema/):
// foxglove.SceneUpdate (with the cube, sphere, cylinder and line primitives cosim writes) and
// foxglove.FrameTransform; plus cosim's own cosim.VehicleState and cosim.RunMoment.
#include <nlohmann/json.hpp>

namespace cosim {

nlohmann::json sceneUpdateSchema();
nlohmann::json frameTransformSchema();
nlohmann::json vehicleStateSchema();
nlohmann::json runMomentSchema();

// {"sec": s, "nsec": ns} of a time in nanoseconds (foxglove "time").
nlohmann::json foxgloveTime(std::uint64_t ns);

}  // namespace cosim
