// The URDF converter walks a robot's tree without recursion (a 20 000-link chain overflowed the
// stack), keeps the depth-first order a recursive walk made, and refuses robots past its size
// limits before urdfdom and MuJoCo spend seconds and gigabytes on them.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "core/input_error.h"
#include "sim/urdf_vehicle.h"

// GCC 12 at -O3 warns falsely inside libstdc++ on "literal" + std::string (GCC bug 105329):
// the strings built below are short and well formed.
#pragma GCC diagnostic ignored "-Wstringop-overflow"
#pragma GCC diagnostic ignored "-Warray-bounds"

// GCC 12 warns -Wrestrict inside libstdc++ for string concatenations once inlined (GCC bug
// 105329, a false positive); this file builds many such strings.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wrestrict"
#endif

using namespace cosim;

namespace {

namespace fs = std::filesystem;

const char* kInertial =
    "<inertial><mass value=\"1\"/><inertia ixx=\"0.01\" iyy=\"0.01\" izz=\"0.01\" ixy=\"0\" "
    "ixz=\"0\" iyz=\"0\"/></inertial>";

std::string link(const std::string& name) {
  return "<link name=\"" + name + "\">" + kInertial + "</link>\n";
}
std::string fixed(const std::string& parent, const std::string& child) {
  return "<joint name=\"" + parent + "_" + child + "\" type=\"fixed\"><parent link=\"" + parent +
         "\"/><child link=\"" + child + "\"/></joint>\n";
}

// The body names addUrdfVehicle makes for `urdf`, in document order; or the InputError's text.
std::vector<std::string> convert(const std::string& urdf, std::string* error = nullptr) {
  const fs::path file =
      fs::temp_directory_path() / ("cosim-tree-" + std::to_string(::getpid()) + ".urdf");
  std::ofstream(file) << urdf;
  tinyxml2::XMLDocument doc;
  tinyxml2::XMLElement* root = doc.NewElement("mujoco");
  doc.InsertEndChild(root);
  tinyxml2::XMLElement* worldbody = root->InsertNewChildElement("worldbody");
  VehicleSpec v;
  v.name = "r";
  v.model_file = file;
  v.kind = VehicleKind::GroundRobot;
  std::vector<std::string> bodies;
  try {
    addUrdfVehicle(doc, worldbody, v, 0.0);
  } catch (const InputError& e) {
    if (error) *error = e.place() + " | " + e.problem();
  }
  // Every body, depth first in document order.
  std::vector<const tinyxml2::XMLElement*> open = {worldbody};
  while (!open.empty()) {
    const tinyxml2::XMLElement* e = open.back();
    open.pop_back();
    if (std::string(e->Name()) == "body") bodies.push_back(e->Attribute("name"));
    std::vector<const tinyxml2::XMLElement*> children;
    for (const auto* c = e->FirstChildElement(); c; c = c->NextSiblingElement())
      children.push_back(c);
    open.insert(open.end(), children.rbegin(), children.rend());
  }
  fs::remove(file);
  return bodies;
}

TEST(UrdfTree, BodiesFollowTheDepthFirstOrderOfTheChildJoints) {
  const std::string urdf = "<robot name=\"t\">" + link("base") + link("a") + link("a1") +
                           link("a2") + link("b") + link("b1") + fixed("base", "a") +
                           fixed("a", "a1") + fixed("a", "a2") + fixed("base", "b") +
                           fixed("b", "b1") + "</robot>";
  std::string error;
  const auto bodies = convert(urdf, &error);
  // The robot has no drive (that is refused after the tree is built): the tree is complete.
  EXPECT_NE(error.find("a ground robot needs a planar root joint"), std::string::npos) << error;
  EXPECT_EQ(bodies, (std::vector<std::string>{"r/base", "r/a", "r/a1", "r/a2", "r/b", "r/b1"}));
}

TEST(UrdfTree, AChainDeeperThanTheLimitIsRefusedNamingItsFirstLinkTooDeep) {
  std::string urdf = "<robot name=\"c\">" + link("l0");
  for (int i = 1; i <= 70; ++i)
    urdf +=
        link("l" + std::to_string(i)) + fixed("l" + std::to_string(i - 1), "l" + std::to_string(i));
  std::string error;
  convert(urdf + "</robot>", &error);
  EXPECT_EQ(error, "link 'l65' | more than 64 links below the base on one branch");
}

TEST(UrdfTree, MoreLinksThanTheLimitAreRefusedBeforeUrdfdomReadsThem) {
  std::string urdf = "<robot name=\"c\">\n";
  for (int i = 0; i <= 1000; ++i) urdf += link("l" + std::to_string(i));
  std::string error;
  convert(urdf + "</robot>", &error);
  EXPECT_EQ(error,
            "line 1002, <link> | more than 1000 links (a ground robot has a few dozen at "
            "most)");
}

}  // namespace
