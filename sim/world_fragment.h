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
//   texture pixels, the number of elements; composite objects (which generate bodies) are refused.
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

// Appends the fragment's sections to `mujoco` (the composed world's root), its file references
// made absolute. Throws InputError(fragment file, "line N, <element>", problem).
void addWorldFragment(tinyxml2::XMLDocument& doc, tinyxml2::XMLElement* mujoco,
                      const std::filesystem::path& fragment);

// The files the fragment names (resolved as above), for fingerprints of what a run reads;
// nothing for a fragment that cannot be read (the run reports that).
std::vector<std::filesystem::path> worldFragmentFiles(const std::filesystem::path& fragment);

}  // namespace cosim
