// world.include: a fragment's files resolve against its own folder, it cannot change the
// scenario's physics options, what it could multiply is bounded before MuJoCo allocates, and its
// errors name the fragment (or the scenario's world.include when it clashes with the rest).
#include "sim/world_fragment.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "core/input_error.h"
#include "sim/scenario.h"
#include "sim/world_model.h"

// GCC 12 at -O3 warns falsely inside libstdc++ on "literal" + std::string (GCC bug 105329):
// the strings built below are short and well formed.
#pragma GCC diagnostic ignored "-Wstringop-overflow"
#pragma GCC diagnostic ignored "-Warray-bounds"

using namespace cosim;

namespace {

namespace fs = std::filesystem;

// A binary STL (MuJoCo reads binary STL): a tetrahedron of 1 m edges.
std::string tetrahedronStl() {
  const float v[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const int faces[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  std::string stl(80, ' ');
  const std::uint32_t n = 4;
  stl.append(reinterpret_cast<const char*>(&n), 4);
  for (const auto& f : faces) {
    const float normal[3] = {0, 0, 0};
    stl.append(reinterpret_cast<const char*>(normal), 12);
    for (int k = 0; k < 3; ++k) stl.append(reinterpret_cast<const char*>(v[f[k]]), 12);
    stl.append(2, '\0');
  }
  return stl;
}

class WorldFragment : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("cosim-fragment-" + std::to_string(::getpid()) + "-" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "parts");
  }
  void TearDown() override { fs::remove_all(dir_); }
  void write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name, std::ios::binary) << text;
  }
  // The scenario (in dir_) including parts/frag.xml.
  Scenario scenario() {
    return parseScenario(
        "world: {bounds: {min: [0, 0, 0], max: [20, 20, 6]}, include: parts/frag.xml}\n"
        "vehicles: [{name: uav1, model: cf2, start: [2, 2, 1], goal: [18, 18, 1]}]\n"
        "sim: {timestep: 0.002, control_rate: 250}\n",
        (dir_ / "s.yaml").string());
  }
  // "file | place | problem" of the InputError building the world throws.
  std::string buildError() {
    try {
      WorldModel::build(scenario());
    } catch (const InputError& e) {
      return e.file() + " | " + e.place() + " | " + e.problem();
    }
    ADD_FAILURE() << "the world was built";
    return "";
  }
  fs::path dir_;
};

TEST_F(WorldFragment, MeshFilesResolveAgainstTheFragmentsFolderNotTheWorkingFolder) {
  write("parts/tetra.stl", tetrahedronStl());
  write("parts/frag.xml",
        "<mujoco>\n  <asset><mesh name=\"tetra\" file=\"tetra.stl\"/></asset>\n"
        "  <worldbody><geom name=\"rock\" type=\"mesh\" mesh=\"tetra\" pos=\"10 10 "
        "0\"/></worldbody>\n"
        "</mujoco>\n");
  const fs::path before = fs::current_path();
  fs::current_path(fs::temp_directory_path());  // not the scenario's, not the fragment's folder
  const WorldModel world = WorldModel::build(scenario());
  fs::current_path(before);
  EXPECT_EQ(world.model()->nmesh, 1);
  EXPECT_GE(mj_name2id(world.model(), mjOBJ_GEOM, "rock"), 0);
}

TEST_F(WorldFragment, TheScenarioKeepsItsTimestepAndAFragmentOptionIsRefused) {
  write("parts/frag.xml", "<mujoco>\n  <worldbody/>\n</mujoco>\n");
  EXPECT_DOUBLE_EQ(WorldModel::build(scenario()).model()->opt.timestep, 0.002);
  write("parts/frag.xml", "<mujoco>\n  <option timestep=\"0.01\"/>\n</mujoco>\n");
  EXPECT_EQ(buildError(), (dir_ / "parts/frag.xml").string() +
                              " | line 2, <option> | a world fragment may not set the world's "
                              "<option> (the scenario does: sim.timestep for the physics step)");
  for (const std::string section : {"compiler", "size", "visual"}) {
    std::string fragment = "<mujoco><";  // piece by piece: GCC 12's -Wrestrict misfires on chains
    fragment += section;
    fragment += "/></mujoco>\n";
    write("parts/frag.xml", fragment);
    std::string problem = "may not set the world's <";
    problem += section;
    problem += '>';
    EXPECT_NE(buildError().find(problem), std::string::npos);
  }
}

TEST_F(WorldFragment, IncludesCompositesAndForeignSectionsAreRefused) {
  write("parts/frag.xml", "<mujoco><worldbody><include file=\"x.xml\"/></worldbody></mujoco>\n");
  EXPECT_NE(buildError().find("line 1, <include> | a world fragment may not include further files"),
            std::string::npos);
  write("parts/frag.xml",
        "<mujoco><worldbody><composite type=\"grid\" count=\"1000 1000 1\"/></worldbody></mujoco>");
  EXPECT_NE(buildError().find("composite objects are not allowed"), std::string::npos);
  write("parts/frag.xml", "<mujoco><actuator/></mujoco>\n");
  EXPECT_NE(buildError().find("<actuator> is not allowed in a world fragment"), std::string::npos);
  write("parts/frag.xml", "<robot/>\n");
  EXPECT_NE(buildError().find("a world fragment is a <mujoco> element"), std::string::npos);
}

TEST_F(WorldFragment, HeightFieldsAndTexturesAreBoundedByWhatTheyDeclare) {
  write("parts/frag.xml",
        "<mujoco><asset><hfield name=\"h\" nrow=\"46341\" ncol=\"46341\" size=\"1 1 1 1\"/>"
        "</asset></mujoco>\n");
  EXPECT_NE(buildError().find("a height field of 46341 x 46341 is more than the 4194304"),
            std::string::npos);
  // A PNG whose header declares 5000 x 5000 pixels (the rest of the file need not be there).
  std::string png = "\x89PNG\r\n\x1a\n";
  png += std::string("\0\0\0\x0dIHDR", 8);
  png += std::string("\0\0\x13\x88\0\0\x13\x88", 8);
  write("parts/big.png", png);
  write("parts/frag.xml",
        "<mujoco><asset><hfield name=\"h\" file=\"big.png\" size=\"1 1 1 1\"/></asset></mujoco>\n");
  EXPECT_NE(buildError().find("the file holds 5000 x 5000 samples"), std::string::npos);
  write("parts/frag.xml",
        "<mujoco><asset><texture name=\"t\" type=\"2d\" builtin=\"checker\" width=\"100000\" "
        "height=\"100000\"/></asset></mujoco>\n");
  EXPECT_NE(buildError().find("a texture of 100000 x 100000"), std::string::npos);
  // MuJoCo's own texture format declaring 65536 x 65536 texels in 8 bytes: MuJoCo's 32-bit check
  // of the file's length (8 + 3 x 65536 x 65536) wraps to 8 and passes.
  write("parts/wrap.tex", std::string("\0\0\x01\0\0\0\x01\0", 8));
  write("parts/frag.xml",
        "<mujoco><asset><texture name=\"t\" type=\"2d\" file=\"wrap.tex\"/></asset></mujoco>\n");
  EXPECT_NE(buildError().find("file=\"wrap.tex\" | the file holds 65536 x 65536 samples"),
            std::string::npos)
      << buildError();
}

// MuJoCo makes a texture that has a `builtin` from its width even when it also names a file, so
// the file's size says nothing: a 1 x 1 PNG beside a built-in cube of width 21000 once let
// MuJoCo ask for 3 x 21000 x 126000 bytes, a size that overflows its int.
TEST_F(WorldFragment, ABuiltInTextureIsBoundedByItsWidthEvenWhenItAlsoNamesAFile) {
  std::string png = "\x89PNG\r\n\x1a\n";
  png += std::string("\0\0\0\x0dIHDR", 8);
  png += std::string("\0\0\0\x01\0\0\0\x01", 8);
  write("parts/dot.png", png);
  write("parts/frag.xml",
        "<mujoco><asset><texture name=\"t\" type=\"cube\" builtin=\"checker\" file=\"dot.png\" "
        "width=\"21000\" height=\"1\"/></asset></mujoco>\n");
  EXPECT_NE(buildError().find("line 1, <texture> | a cube face of 21000 x 21000 is more than the "
                              "4194304 samples allowed"),
            std::string::npos)
      << buildError();
}

TEST_F(WorldFragment, AFileItNamesMustBeARegularFileBesideIt) {
  write("parts/frag.xml", "<mujoco><asset><mesh name=\"m\" file=\"gone.stl\"/></asset></mujoco>\n");
  EXPECT_NE(buildError().find("file=\"gone.stl\" | cannot open mesh, height field or texture file: "
                              "file not found (" +
                              (dir_ / "parts/gone.stl").string() + ")"),
            std::string::npos);
  write("parts/frag.xml",
        "<mujoco><asset><mesh name=\"m\" file=\"/dev/zero\"/></asset></mujoco>\n");
  EXPECT_NE(buildError().find("is not a regular file"), std::string::npos);
}

TEST_F(WorldFragment, ErrorsNameTheFragmentOrTheScenarioKeyNotAVehicleModel) {
  // MuJoCo refuses the fragment itself: its file and MuJoCo's words, on one line.
  write("parts/frag.xml",
        "<mujoco>\n<worldbody>\n<geom type=\"pyramid\"/>\n</worldbody>\n</mujoco>\n");
  const std::string own = buildError();
  EXPECT_EQ(own.rfind((dir_ / "parts/frag.xml").string() + " |  | MuJoCo cannot compile this world "
                                                           "fragment (world.include): ",
                      0),
            0u)
      << own;
  EXPECT_NE(own.find("pyramid"), std::string::npos) << own;
  EXPECT_EQ(own.find('\n'), std::string::npos);
  // It compiles alone but clashes with the composed world (the floor's name).
  write(
      "parts/frag.xml",
      "<mujoco><worldbody><geom name=\"floor\" type=\"sphere\" size=\"1\"/></worldbody></mujoco>");
  const std::string clash = buildError();
  EXPECT_EQ(
      clash.rfind((dir_ / "s.yaml").string() + " | key world.include | the fragment " +
                      (dir_ / "parts/frag.xml").string() + " does not fit the composed world: ",
                  0),
      0u)
      << clash;
}

// Limits per element let ten textures of the largest size through (2.9 GB) or forty height
// fields (22.7 GB): the fragment as a whole has a budget, counted before MuJoCo allocates.
TEST_F(WorldFragment, TexturesAndHeightFieldsCountAgainstOneBudgetForTheWholeFragment) {
  std::string four;  // 1024 x 1024 cube textures, 72 MB each with their six faces: 3 fit
  for (int i = 0; i < 4; ++i)
    four += "\n<texture name=\"t" + std::to_string(i) +
            "\" type=\"cube\" builtin=\"checker\" width=\"1024\" height=\"1024\"/>";
  write("parts/frag.xml", "<mujoco><asset>" + four + "\n</asset></mujoco>\n");
  const std::string textures = buildError();
  EXPECT_NE(textures.find("parts/frag.xml | line 5, <texture> | the fragment's height fields, "
                          "textures and meshes need about 288 MB"),
            std::string::npos)
      << textures;
  EXPECT_NE(textures.find("more than the 256 MB a world fragment may use"), std::string::npos);

  std::string seven;  // 512 x 512 height fields, 44 MB each: 5 fit, the sixth does not
  for (int i = 0; i < 7; ++i)
    seven += "<hfield name=\"h" + std::to_string(i) +
             "\" nrow=\"512\" ncol=\"512\" size=\"1 1 1 1\"/>\n";
  write("parts/frag.xml", "<mujoco><asset>\n" + seven + "</asset></mujoco>\n");
  EXPECT_NE(buildError().find("line 7, <hfield> | the fragment's height fields, textures and "
                              "meshes need about 267 MB"),
            std::string::npos)
      << buildError();

  // Textures and height fields share the budget: 5 fields fit, and 1 texture more does not.
  write("parts/frag.xml", "<mujoco><asset>\n" + seven.substr(0, seven.size() * 5 / 7) +
                              "<texture name=\"t\" type=\"cube\" builtin=\"flat\" width=\"1024\" "
                              "height=\"1024\"/>\n</asset></mujoco>\n");
  EXPECT_NE(buildError().find("line 7, <texture>"), std::string::npos) << buildError();
}

TEST_F(WorldFragment, NumbersThatAreNotFiniteOrBeyondTheWorldsScaleAreRefusedWithTheirAttribute) {
  write("parts/frag.xml",
        "<mujoco>\n<worldbody>\n<geom type=\"box\" size=\"nan nan nan\" pos=\"10 10 1\"/>\n"
        "</worldbody></mujoco>\n");
  EXPECT_EQ(buildError(), (dir_ / "parts/frag.xml").string() +
                              " | line 3, <geom>, attribute size | 'nan' is not a finite number");
  write("parts/frag.xml",
        "<mujoco><worldbody>\n<geom type=\"sphere\" size=\"1e308\" pos=\"10 10 1\"/>\n"
        "</worldbody></mujoco>\n");
  EXPECT_NE(buildError().find("line 2, <geom>, attribute size | 1e308 m is beyond the world's "
                              "scale (at most 10000 m from the origin)"),
            std::string::npos)
      << buildError();
  write("parts/frag.xml",
        "<mujoco><worldbody><body pos=\"1 1 1\" quat=\"1 0 0 inf\">\n"
        "<geom type=\"capsule\" size=\"0.1\" fromto=\"0 0 0 -2e4 0 1\"/></body>\n"
        "</worldbody></mujoco>\n");
  EXPECT_NE(buildError().find("line 1, <body>, attribute quat | 'inf' is not a finite number"),
            std::string::npos)
      << buildError();
  // Within the scale, finite: built.
  write("parts/frag.xml",
        "<mujoco><worldbody><geom type=\"box\" size=\"0.5 0.5 0.5\" pos=\"10 10 1\" "
        "rgba=\"1 0 0 1\"/></worldbody></mujoco>\n");
  EXPECT_NO_THROW(WorldModel::build(scenario()));
}

}  // namespace
