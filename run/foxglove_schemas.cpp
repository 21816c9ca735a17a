#include "run/foxglove_schemas.h"

namespace cosim {

namespace {

using nlohmann::json;

json object(const std::string& title, json properties) {
  json o = {{"type", "object"}, {"properties", std::move(properties)}};
  if (!title.empty()) o["title"] = title;
  return o;
}
json number() {
  return {{"type", "number"}};
}
json integer() {
  return {{"type", "integer"}};
}
json text() {
  return {{"type", "string"}};
}
json arrayOf(json items) {
  return {{"type", "array"}, {"items", std::move(items)}};
}
json vector3() {
  return object("foxglove.Vector3", {{"x", number()}, {"y", number()}, {"z", number()}});
}
json point3() {
  return object("foxglove.Point3", {{"x", number()}, {"y", number()}, {"z", number()}});
}
json quaternion() {
  return object("foxglove.Quaternion",
                {{"x", number()}, {"y", number()}, {"z", number()}, {"w", number()}});
}
json color() {
  return object("foxglove.Color",
                {{"r", number()}, {"g", number()}, {"b", number()}, {"a", number()}});
}
json pose() {
  return object("foxglove.Pose", {{"position", vector3()}, {"orientation", quaternion()}});
}
json time() {
  return object("time", {{"sec", integer()}, {"nsec", integer()}});
}
json duration() {
  return object("duration", {{"sec", integer()}, {"nsec", integer()}});
}

}  // namespace

json foxgloveTime(std::uint64_t ns) {
  return {{"sec", ns / 1000000000u}, {"nsec", ns % 1000000000u}};
}

json sceneUpdateSchema() {
  const json cube =
      object("foxglove.CubePrimitive", {{"pose", pose()}, {"size", vector3()}, {"color", color()}});
  const json sphere = object("foxglove.SpherePrimitive",
                             {{"pose", pose()}, {"size", vector3()}, {"color", color()}});
  const json cylinder = object("foxglove.CylinderPrimitive", {{"pose", pose()},
                                                              {"size", vector3()},
                                                              {"bottom_scale", number()},
                                                              {"top_scale", number()},
                                                              {"color", color()}});
  // type: 0 LINE_STRIP, 1 LINE_LOOP, 2 LINE_LIST
  const json line = object("foxglove.LinePrimitive", {{"type", integer()},
                                                      {"pose", pose()},
                                                      {"thickness", number()},
                                                      {"scale_invariant", {{"type", "boolean"}}},
                                                      {"points", arrayOf(point3())},
                                                      {"color", color()},
                                                      {"colors", arrayOf(color())},
                                                      {"indices", arrayOf(integer())}});
  const json entity = object("foxglove.SceneEntity", {{"timestamp", time()},
                                                      {"frame_id", text()},
                                                      {"id", text()},
                                                      {"lifetime", duration()},
                                                      {"frame_locked", {{"type", "boolean"}}},
                                                      {"cubes", arrayOf(cube)},
                                                      {"spheres", arrayOf(sphere)},
                                                      {"cylinders", arrayOf(cylinder)},
                                                      {"lines", arrayOf(line)}});
  const json deletion = object("foxglove.SceneEntityDeletion",
                               {{"timestamp", time()}, {"type", integer()}, {"id", text()}});
  json s = object("foxglove.SceneUpdate",
                  {{"deletions", arrayOf(deletion)}, {"entities", arrayOf(entity)}});
  s["description"] = "An update to the entities displayed in a 3D scene";
  return s;
}

json frameTransformSchema() {
  json s = object("foxglove.FrameTransform", {{"timestamp", time()},
                                              {"parent_frame_id", text()},
                                              {"child_frame_id", text()},
                                              {"translation", vector3()},
                                              {"rotation", quaternion()}});
  s["description"] = "A transform between two reference frames in 3D space";
  return s;
}

json vehicleStateSchema() {
  return object("cosim.VehicleState", {{"t", number()},
                                       {"position", vector3()},
                                       {"reference", vector3()},
                                       {"estimate", vector3()},
                                       {"error_m", number()},
                                       {"estimate_error_m", number()},
                                       {"speed_mps", number()},
                                       {"thrust_n", arrayOf(number())}});
}

json runMomentSchema() {
  return object("cosim.RunMoment", {{"kind", text()},
                                    {"t", number()},
                                    {"vehicle", text()},
                                    {"value_m", number()},
                                    {"label", text()}});
}

}  // namespace cosim
