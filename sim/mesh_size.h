#pragma once
// How big a <mesh> of a world fragment is, counted before MuJoCo sees it: from the header of its
// file (binary STL, MuJoCo's MSH) or the lines of an OBJ file, or from its inline vertex and face
// arrays. MuJoCo 2.2.2's compiler takes time quadratic in a mesh's vertices (it maps every face
// of the mesh's convex hull back to its vertices by a linear search: measured, docs/
// scenario_keys.md, Limits), and it cannot be interrupted while it compiles, so these counts
// bound the time a world takes to load (sim/world_fragment.h).
#include <tinyxml2.h>

#include <string>

namespace cosim {

struct MeshSize {
  long vertices = 0;   // distinct positions, as MuJoCo keeps them
  long triangles = 0;  // faces, each polygon counted as the triangles it is cut into
  bool known = false;  // false: not a format counted here, or the file contradicts its header
                       // (MuJoCo then refuses it with its own message)
};

// A mesh file's size, by its extension (.stl, .obj or .msh, any case). For a binary STL the
// triangles come from its header; its vertices are the distinct corners among them, counted only
// when the triangles are at most `max_triangles` (beyond that the file is refused on its
// triangles alone, without reading them).
MeshSize meshFileSize(const std::string& file_name, const std::string& bytes, long max_triangles);

// An inline mesh's size: its `vertex` attribute's numbers / 3 and its `face` attribute's / 3.
MeshSize inlineMeshSize(const tinyxml2::XMLElement* mesh);

}  // namespace cosim
