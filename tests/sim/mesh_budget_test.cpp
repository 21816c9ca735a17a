// A world fragment's meshes are counted before MuJoCo compiles them (its compile time grows with
// the square of a mesh's vertices and cannot be interrupted): vertices and triangles of each
// mesh and of all of them together, from a binary STL's header and corners, an MSH header, an
// OBJ's lines or the inline arrays. Over a budget: one line naming the fragment, the mesh and
// the budget.
#include <gtest/gtest.h>
#include <tinyxml2.h>
#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "core/input_error.h"
#include "sim/mesh_size.h"
#include "sim/scenario.h"
#include "sim/world_fragment.h"
#include "sim/world_model.h"

// GCC 12 warns -Wrestrict, -Warray-bounds, -Wstringop-overflow inside libstdc++ where a string is
// assigned or concatenated once inlined (GCC bug 105329, a false positive).
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wrestrict"
#pragma GCC diagnostic ignored "-Warray-bounds"
#pragma GCC diagnostic ignored "-Wstringop-overflow"
#endif

using namespace cosim;

namespace {

namespace fs = std::filesystem;

void appendFloats(std::string& out, const std::vector<float>& v) {
  out.append(reinterpret_cast<const char*>(v.data()), 4 * v.size());
}

// A binary STL of `n` triangles. shared: a fan around one corner, 2 + n distinct corners;
// otherwise every corner distinct (3n).
std::string stl(std::uint32_t n, bool shared) {
  std::string out(80, ' ');
  out.append(reinterpret_cast<const char*>(&n), 4);
  for (std::uint32_t t = 0; t < n; ++t) {
    const float x = static_cast<float>(t);
    appendFloats(out, {0, 0, 1});
    if (shared)
      appendFloats(out, {0, 0, 0, x, 1, 0, x + 1, 1, 0});
    else
      appendFloats(out, {x, 0, 0, x, 1, 0, x, 0, 1});
    out.append(2, '\0');
  }
  return out;
}

// An inline mesh of `n` vertices on a helix (no faces: MuJoCo takes their convex hull).
std::string inlineMesh(const std::string& name, int n) {
  std::ostringstream v;
  for (int i = 0; i < n; ++i)
    v << (i % 97) * 0.01 << ' ' << (i % 89) * 0.01 << ' ' << i * 1e-4 << ' ';
  return "<mesh name=\"" + name + "\" vertex=\"" + v.str() + "\"/>";
}

class MeshBudget : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("cosim-mesh-budget-" + std::to_string(::getpid()) + "-" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  void write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name, std::ios::binary) << text;
  }
  // "file | place | problem" of the InputError that building a world with `assets` throws, or
  // "" if it builds.
  std::string buildError(const std::string& assets) {
    write("frag.xml", "<mujoco>\n<asset>" + assets + "</asset>\n</mujoco>\n");
    try {
      WorldModel::build(parseScenario(
          "world: {bounds: {min: [0, 0, 0], max: [20, 20, 6]}, include: frag.xml}\n"
          "vehicles: [{name: uav1, model: cf2, start: [2, 2, 1], goal: [18, 18, 1]}]\n",
          (dir_ / "s.yaml").string()));
    } catch (const InputError& e) {
      return e.file() + " | " + e.place() + " | " + e.problem();
    }
    return "";
  }
  fs::path dir_;
};

TEST(MeshSize, ABinaryStlCountsItsHeadersTrianglesAndItsDistinctCorners) {
  const MeshSize fan = meshFileSize("fan.STL", stl(10, true), kMaxMeshTriangles);
  EXPECT_TRUE(fan.known);
  EXPECT_EQ(fan.triangles, 10);
  EXPECT_EQ(fan.vertices, 12);  // the shared corner once, then 11 along the rim
  const MeshSize soup = meshFileSize("soup.stl", stl(10, false), kMaxMeshTriangles);
  EXPECT_EQ(soup.vertices, 30);
  // Beyond the triangle budget the corners are not read: 3 per triangle at most.
  const MeshSize big = meshFileSize("big.stl", stl(30, true), 20);
  EXPECT_EQ(big.triangles, 30);
  EXPECT_EQ(big.vertices, 90);
  // An ASCII STL reads as an absurd count longer than the file: left to MuJoCo's own message.
  EXPECT_FALSE(meshFileSize("a.stl", "solid a\n" + std::string(100, ' '), 1000).known);
}

TEST(MeshSize, MshAndObjFilesAndInlineArraysAreCounted) {
  std::string msh;
  const std::int32_t header[4] = {4, 0, 0, 2};
  msh.append(reinterpret_cast<const char*>(header), 16);
  msh.append(4 * 12 + 2 * 12, '\0');
  const MeshSize m = meshFileSize("m.msh", msh, kMaxMeshTriangles);
  EXPECT_TRUE(m.known);
  EXPECT_EQ(m.vertices, 4);
  EXPECT_EQ(m.triangles, 2);
  EXPECT_FALSE(meshFileSize("m.msh", msh + "x", kMaxMeshTriangles).known);  // not its length

  // A quad and a pentagon: 2 + 3 triangles.
  const MeshSize obj =
      meshFileSize("q.obj",
                   "# c\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 2 2\nvn 0 0 1\nf 1 2 3 4\n"
                   "f 1/1 2/2 3/3 4/4 5/5\n",
                   kMaxMeshTriangles);
  EXPECT_EQ(obj.vertices, 5);
  EXPECT_EQ(obj.triangles, 5);

  tinyxml2::XMLDocument doc;
  doc.Parse("<mesh vertex=\"0 0 0  1 0 0\n 0 1 0  0 0 1\" face=\"0 1 2 0 2 3\"/>");
  const MeshSize inline_mesh = inlineMeshSize(doc.RootElement());
  EXPECT_EQ(inline_mesh.vertices, 4);
  EXPECT_EQ(inline_mesh.triangles, 2);
}

TEST_F(MeshBudget, AMeshOverTheVertexBudgetIsRefusedNamingTheFragmentTheMeshAndTheBudget) {
  // 3334 triangles of distinct corners: 10002 vertices, one mesh's budget is 10000.
  write("soup.stl", stl(3334, false));
  EXPECT_EQ(buildError("<mesh name=\"rock\" file=\"soup.stl\"/>"),
            (dir_ / "frag.xml").string() +
                " | line 2, <mesh> | mesh 'rock': 10002 vertices in this mesh, more than the "
                "10000 allowed (MuJoCo's compile time grows with the square of a mesh's "
                "vertices; simplify or decimate the mesh)");
  // 3333 of them (9999 vertices) are within it.
  write("soup.stl", stl(3333, false));
  EXPECT_EQ(buildError("<mesh name=\"rock\" file=\"soup.stl\"/>"), "");
}

TEST_F(MeshBudget, AnStlOverTheTriangleBudgetIsRefusedFromItsHeader) {
  write("fan.stl", stl(20001, true));
  EXPECT_NE(buildError("<mesh file=\"fan.stl\"/>")
                .find("mesh fan.stl: 20001 triangles in this mesh, more than the 20000 allowed"),
            std::string::npos);
}

TEST_F(MeshBudget, AnInlineMeshIsCountedAndTheFragmentsMeshesShareOneBudget) {
  EXPECT_NE(buildError(inlineMesh("cloud", 10001))
                .find("mesh 'cloud': 10001 vertices in this mesh, more than the 10000"),
            std::string::npos);
  // Three meshes of 8000 vertices: the third passes the fragment's 20000.
  const std::string error =
      buildError(inlineMesh("a", 8000) + inlineMesh("b", 8000) + inlineMesh("c", 8000));
  EXPECT_NE(error.find("mesh 'c': 24000 vertices in the fragment's meshes up to here, more than "
                       "the 20000 allowed"),
            std::string::npos)
      << error;
}

}  // namespace
