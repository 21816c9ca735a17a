#pragma once
// world.include: an MJCF fragment with more geometry for a scenario's world (a <mujoco> file
// whose <asset>, <default>, <worldbody> and <contact> sections join the composed world).
// Checked before MuJoCo sees it, so that its faults are reported against the fragment:
// - only those four sections: <option>, <compiler>, <size> and the like belong to the scenario
//   (sim.timestep sets the physics step; a fragment must not change it behind its back), and a
//   fragment includes no further files;
// - files it names (meshes, height fields, textures, skins) are relative to the fragment's own
//   folder, must be regular files of bounded size, and are given to MuJoCo as absolute paths;
// - what a few bytes could multiply is bounded before MuJoCo allocates it: height field samples,
//   texture pixels, the number of elements, and the memory all of them cost together;
//   composite objects (which generate bodies) are refused;
// - numbers are finite, and positions and sizes within the world's scale (NaN sizes passed
//   MuJoCo's compiler; 1e308 made the simulation diverge).
#include <tinyxml2.h>

#include <filesystem>
#include <vector>

namespace cosim {

// Height field samples (nrow x ncol) a fragment may declare or load: 2048 x 2048 (16 MB of
// floats). A 38000 x 38000 field took 5.6 GB before MuJoCo gave up.
constexpr long kMaxHeightFieldSamples = 2048L * 2048L;
// Pixels of one texture (per cube face): 2048 x 2048.
constexpr long kMaxTexturePixels = 2048L * 2048L;
// Elements of one fragment (each geom, body, asset...): MuJoCo's compiler and collision phase
// scale with them (see kMaxGridMapBoxes).
constexpr long kMaxFragmentElements = 20000;

// Meshes (sim/mesh_size.h counts them before MuJoCo sees them). MuJoCo 2.2.2 compiles a mesh in
// time quadratic in its vertices (mapping its convex hull's faces back to its vertices), in one
// uninterruptible call: measured here (CPU time of mj_loadXML, one mesh whose vertices all lie
// on its hull, the worst case), 5000 vertices 0.06 s, 10000 0.18 s, 20000 0.61 s; a 50000-
// triangle closed STL (25439 vertices) 1.0 s, and 18 s of wall time on this 2-core machine
// while it was shared. A mesh may have 10000 vertices and 20000 triangles (a closed surface
// of V vertices has 2V - 4 triangles); a fragment's meshes together twice that, so its meshes
// compile in under 0.4 s of CPU time and a stop request waits seconds at most.
constexpr long kMaxMeshVertices = 10000;
constexpr long kMaxMeshTriangles = 20000;
constexpr long kMaxFragmentMeshVertices = 20000;
constexpr long kMaxFragmentMeshTriangles = 40000;

// The memory a whole fragment may cost a run, counted before MuJoCo allocates anything: its
// height fields, textures (every face of a cube or skybox, built-in ones too) and mesh files
// together. 256 MB: the bundled default scenario's run peaks at 189 MB (measured, --no-video),
// so a run with a fragment stays under half a gigabyte, and a sweep can run one job per core on
// a machine with 1 GB a core. Limits per element alone let ten textures of the largest size
// through (2.9 GB), or forty height fields (22.7 GB).
constexpr long kFragmentMemoryBudget = 256L << 20;
// Bytes a run holds per height field sample: measured, one 1024 x 1024 height field raised the
// default scenario's peak by 187 MB, 178 bytes a sample (the renderer keeps two triangles with
// normals a sample, 144 bytes; the model and the compiler a float each).
constexpr long kBytesPerHeightFieldSample = 178;
// Bytes per texel of each face: measured, one 1024 x 1024 cube texture raised the peak by 71 MB,
// 11.3 bytes a texel of its six faces (RGB in the compiler, in the model, and in OpenGL with its
// mipmaps).
constexpr long kBytesPerTexel = 12;
// How far from the world's origin a fragment's positions and sizes may reach, m: any cosim world
// fits well inside 10 km, and 1e308 m made the simulation diverge.
constexpr double kMaxFragmentCoordinate = 1e4;

// Appends the fragment's sections to `mujoco` (the composed world's root), its file references
// made absolute. Throws InputError(fragment file, "line N, <element>", problem).
void addWorldFragment(tinyxml2::XMLDocument& doc, tinyxml2::XMLElement* mujoco,
                      const std::filesystem::path& fragment);

// The files the fragment names (resolved as above), for fingerprints of what a run reads;
// nothing for a fragment that cannot be read (the run reports that).
std::vector<std::filesystem::path> worldFragmentFiles(const std::filesystem::path& fragment);

}  // namespace cosim
