#include "sim/mesh_size.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdint>
#include <cstring>
#include <vector>

namespace cosim {

namespace {

std::string lowerExtension(const std::string& file_name) {
  const std::size_t dot = file_name.find_last_of('.');
  std::string ext = dot == std::string::npos ? "" : file_name.substr(dot + 1);
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

std::int32_t int32At(const std::string& bytes, std::size_t at) {
  std::int32_t v = 0;
  std::memcpy(&v, bytes.data() + at, 4);
  return v;
}

// Binary STL: an 80-byte header, a uint32 triangle count, then 50 bytes a triangle (normal,
// three corners of three float32, two attribute bytes). A file shorter than its count says is
// not counted: MuJoCo refuses it (an ASCII STL reads as an absurd count).
MeshSize stlSize(const std::string& bytes, long max_triangles) {
  MeshSize size;
  if (bytes.size() < 84) return size;
  std::uint32_t count = 0;
  std::memcpy(&count, bytes.data() + 80, 4);
  const long triangles = static_cast<long>(count);
  if (84 + 50 * static_cast<std::uint64_t>(count) > bytes.size()) return size;
  size.known = true;
  size.triangles = triangles;
  if (triangles > max_triangles) {
    size.vertices = 3 * triangles;  // at most; refused on its triangles anyway
    return size;
  }
  // MuJoCo merges the corners that repeat a position (the same three floats): count those.
  std::vector<std::array<std::uint32_t, 3>> corners(3 * static_cast<std::size_t>(triangles));
  for (long t = 0; t < triangles; ++t)
    for (int c = 0; c < 3; ++c)
      std::memcpy(corners[3 * t + c].data(), bytes.data() + 84 + 50 * t + 12 + 12 * c, 12);
  std::sort(corners.begin(), corners.end());
  size.vertices = std::unique(corners.begin(), corners.end()) - corners.begin();
  return size;
}

// MuJoCo's MSH: int32 nvertex, nnormal, ntexcoord, nface, then 3 floats a vertex and a normal, 2
// a texture coordinate, 3 ints a face. Counted only when the file is as long as that says.
MeshSize mshSize(const std::string& bytes) {
  MeshSize size;
  if (bytes.size() < 16) return size;
  const std::int64_t nv = int32At(bytes, 0), nn = int32At(bytes, 4), nt = int32At(bytes, 8),
                     nf = int32At(bytes, 12);
  if (nv < 0 || nn < 0 || nt < 0 || nf < 0) return size;
  if (16 + 12 * nv + 12 * nn + 8 * nt + 12 * nf != static_cast<std::int64_t>(bytes.size()))
    return size;
  size.known = true;
  size.vertices = static_cast<long>(nv);
  size.triangles = static_cast<long>(nf);
  return size;
}

// OBJ: a line "v x y z" per vertex, "f a b c ..." per polygon (cut into its corners - 2
// triangles).
MeshSize objSize(const std::string& bytes) {
  MeshSize size;
  size.known = true;
  std::size_t at = 0;
  while (at < bytes.size()) {
    std::size_t end = bytes.find('\n', at);
    if (end == std::string::npos) end = bytes.size();
    std::size_t p = at;
    while (p < end && (bytes[p] == ' ' || bytes[p] == '\t')) ++p;
    const bool blank_after = p + 1 < end && (bytes[p + 1] == ' ' || bytes[p + 1] == '\t');
    if (blank_after && bytes[p] == 'v') ++size.vertices;
    if (blank_after && bytes[p] == 'f') {
      long corners = 0;
      bool in_token = false;
      for (std::size_t k = p + 1; k < end; ++k) {
        const bool blank = bytes[k] == ' ' || bytes[k] == '\t' || bytes[k] == '\r';
        if (!blank && !in_token) ++corners;
        in_token = !blank;
      }
      size.triangles += std::max(0L, corners - 2);
    }
    at = end + 1;
  }
  return size;
}

// How many numbers a whitespace-separated list holds.
long numbersIn(const char* text) {
  long n = 0;
  bool in_token = false;
  for (const char* p = text; p && *p; ++p) {
    const bool blank = std::isspace(static_cast<unsigned char>(*p)) != 0;
    if (!blank && !in_token) ++n;
    in_token = !blank;
  }
  return n;
}

}  // namespace

MeshSize meshFileSize(const std::string& file_name, const std::string& bytes, long max_triangles) {
  const std::string ext = lowerExtension(file_name);
  if (ext == "stl") return stlSize(bytes, max_triangles);
  if (ext == "msh") return mshSize(bytes);
  if (ext == "obj") return objSize(bytes);
  return {};
}

MeshSize inlineMeshSize(const tinyxml2::XMLElement* mesh) {
  MeshSize size;
  size.known = true;
  size.vertices = numbersIn(mesh->Attribute("vertex")) / 3;
  size.triangles = numbersIn(mesh->Attribute("face")) / 3;
  return size;
}

}  // namespace cosim
