#include "sim/scenario_input_files.h"

#include <algorithm>

#include "core/input_error.h"
#include "sim/scenario.h"
#include "sim/urdf_vehicle.h"
#include "sim/world_fragment.h"
#include "sim/yaml_document.h"
#include "sim/yaml_reader.h"

namespace cosim {

namespace {

YAML::Node member(const YAML::Node& n, const char* key) {
  return n.IsDefined() && n.IsMap() ? n[key] : YAML::Node();
}

// A scalar's text, or "" for anything else.
std::string scalarText(const YAML::Node& n) {
  return n.IsDefined() && n.IsScalar() ? n.Scalar() : std::string();
}

std::filesystem::path relativeTo(const std::filesystem::path& dir, const std::string& written) {
  const std::filesystem::path p(written);
  return p.is_absolute() ? p : dir / p;
}

}  // namespace

std::vector<std::filesystem::path> scenarioInputFiles(const std::string& text,
                                                      const std::string& file,
                                                      const std::vector<std::string>& overrides) {
  std::vector<std::filesystem::path> files;
  YAML::Node root;
  try {
    root = loadYamlDocument(text, file);
    for (const auto& o : overrides) applyYamlOverride(root, o);
  } catch (const InputError&) {
    return files;  // the run refuses the scenario itself
  }
  const std::filesystem::path dir = std::filesystem::path(file).parent_path();
  const YAML::Node world = member(root, "world");
  if (const std::string map = scalarText(member(member(world, "grid_map"), "file")); !map.empty())
    files.push_back(relativeTo(dir, map));
  if (const std::string inc = scalarText(member(world, "include")); !inc.empty()) {
    files.push_back(relativeTo(dir, inc));
    for (const auto& f : worldFragmentFiles(files.back())) files.push_back(f);
  }
  const YAML::Node vehicles = member(root, "vehicles");
  if (vehicles.IsDefined() && vehicles.IsSequence())
    for (const auto& v : vehicles) {
      if (const std::string ref = scalarText(member(member(v, "reference"), "file")); !ref.empty())
        files.push_back(relativeTo(dir, ref));
      if (const std::string airframe = scalarText(member(v, "airframe")); !airframe.empty())
        files.push_back(relativeTo(dir, airframe));
      const std::string model = scalarText(member(v, "model"));
      if (model.empty()) continue;
      VehicleKind kind = VehicleKind::Quadrotor;
      files.push_back(resolveModelFile(model, dir, kind));
      if (kind == VehicleKind::GroundRobot)
        for (const auto& m : urdfMeshFiles(files.back())) files.push_back(m);
    }
  // Without repeats (a team of one model lists it once), in first-seen order.
  std::vector<std::filesystem::path> unique;
  for (auto& f : files) {
    f = f.lexically_normal();
    if (std::find(unique.begin(), unique.end(), f) == unique.end()) unique.push_back(f);
  }
  return unique;
}

}  // namespace cosim
