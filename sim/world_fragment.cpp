#include "sim/world_fragment.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include "core/input_error.h"
#include "core/input_file.h"
#include "sim/mesh_size.h"

namespace cosim {

namespace {

using tinyxml2::XMLDocument;
using tinyxml2::XMLElement;

constexpr std::uintmax_t kMaxAssetFileBytes = 32u << 20;  // one mesh, height field or texture

const char* const kAllowedSections[] = {"asset", "default", "worldbody", "contact"};
const char* const kFileAttributes[] = {"file",     "fileright", "fileleft", "fileup",
                                       "filedown", "filefront", "fileback"};
// Attributes whose value is a list of numbers (MJCF's geometry, frames, inertia, materials),
// besides the lengths pos, size, fromto and scale.
const char* const kNumericAttributes[] = {
    "quat",      "axisangle", "euler",     "xyaxes",      "zaxis",       "mass",    "density",
    "friction",  "margin",    "gap",       "solref",      "solimp",      "rgba",    "range",
    "damping",   "stiffness", "armature",  "diaginertia", "fullinertia", "refquat", "refpos",
    "texrepeat", "specular",  "shininess", "reflectance", "emission",    "rgb1",    "rgb2",
    "markrgb",   "random",    "axis",      "dir",         "width"};

std::string at(const XMLElement* e) {
  return "line " + std::to_string(e->GetLineNum()) + ", <" + e->Name() + ">";
}

// The (width, height) a PNG file declares in its header, or (0, 0) if it is not a PNG.
std::array<long, 2> pngSize(const std::string& bytes) {
  static const unsigned char kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  if (bytes.size() < 24 || std::memcmp(bytes.data(), kSignature, 8) != 0) return {0, 0};
  const auto big = [&](std::size_t i) {
    long v = 0;
    for (std::size_t k = 0; k < 4; ++k) v = (v << 8) | static_cast<unsigned char>(bytes[i + k]);
    return v;
  };
  return {big(16), big(20)};
}

class FragmentChecker {
 public:
  explicit FragmentChecker(const std::filesystem::path& file)
      : file_(file.string()), dir_(std::filesystem::absolute(file).parent_path()) {}

  void checkSection(XMLElement* section) {
    const std::string name = section->Name();
    if (name == "option" || name == "compiler" || name == "size" || name == "visual" ||
        name == "statistic")
      fail(section, "a world fragment may not set the world's <" + name +
                        "> (the scenario does: sim.timestep for the physics step)");
    if (name == "include") fail(section, "a world fragment may not include further files");
    bool allowed = false;
    for (const char* a : kAllowedSections) allowed = allowed || name == a;
    if (!allowed)
      fail(
          section,
          "<" + name + "> is not allowed in a world fragment (asset, default, worldbody, contact)");
    // Every element below, in document order (the budget is passed at the element that a
    // reader of the file would count to), without recursion (tinyxml2 bounds the depth at 100).
    std::vector<XMLElement*> open = {section};
    while (!open.empty()) {
      XMLElement* e = open.back();
      open.pop_back();
      checkElement(e);
      for (XMLElement* c = e->LastChildElement(); c; c = c->PreviousSiblingElement())
        open.push_back(c);
    }
  }

 private:
  [[noreturn]] void fail(const XMLElement* e, const std::string& problem) const {
    throw InputError(file_, at(e), problem);
  }

  long attribute(const XMLElement* e, const char* name) const {
    const char* v = e->Attribute(name);
    if (!v) return 0;
    char* end = nullptr;
    const long n = std::strtol(v, &end, 10);
    if (end == v) fail(e, std::string("'") + name + "' must be a whole number");
    return n;
  }

  void checkElement(XMLElement* e) {
    if (++elements_ > kMaxFragmentElements)
      fail(e, "more than " + std::to_string(kMaxFragmentElements) + " elements");
    const std::string name = e->Name();
    if (name == "include") fail(e, "a world fragment may not include further files");
    if (name == "composite")
      fail(e, "composite objects are not allowed in a world fragment (they generate bodies)");
    checkNumbers(e);
    long file_samples = 0;  // samples or texels the element's files hold
    for (const char* attr : kFileAttributes)
      if (const char* f = e->Attribute(attr)) file_samples += resolveFile(e, attr, f);
    if (name == "hfield") {
      const long rows = attribute(e, "nrow"), cols = attribute(e, "ncol");
      checkSize(e, rows, cols, kMaxHeightFieldSamples, "height field");
      // MuJoCo reads the samples from the file when there is one, else allocates nrow x ncol.
      spend(e, (e->Attribute("file") ? file_samples : rows * cols) * kBytesPerHeightFieldSample);
    }
    if (name == "texture") {
      const long width = attribute(e, "width"), height = attribute(e, "height");
      checkSize(e, width, height, kMaxTexturePixels, "texture");
      spend(e, textureTexels(e, width, height, file_samples) * kBytesPerTexel);
    }
    if (name == "mesh" && e->Attribute("file")) spend(e, mesh_file_bytes_);
    if (name == "mesh") countMesh(e, e->Attribute("file") ? mesh_file_size_ : inlineMeshSize(e));
  }

  // A mesh's vertices and triangles, against the budgets of one mesh and of the whole fragment
  // (MuJoCo compiles them uninterruptibly, in time quadratic in each mesh's vertices).
  void countMesh(const XMLElement* e, const MeshSize& size) {
    if (!size.known) return;
    const char* given = e->Attribute("name");
    const char* file = e->Attribute("file");
    const std::string mesh =
        std::string("mesh ") + (given  ? "'" + std::string(given) + "'"
                                : file ? std::filesystem::path(file).filename().string()
                                       : std::string("(unnamed)"));
    const auto over = [&](long count, long limit, const std::string& what, const std::string& of) {
      if (count > limit)
        fail(e, mesh + ": " + std::to_string(count) + " " + what + of + ", more than the " +
                    std::to_string(limit) + " allowed (MuJoCo's compile time grows with the " +
                    "square of a mesh's vertices; simplify or decimate the mesh)");
    };
    // Triangles first: an STL over its triangle budget has its vertices only bounded, not read.
    over(size.triangles, kMaxMeshTriangles, "triangles", " in this mesh");
    over(size.vertices, kMaxMeshVertices, "vertices", " in this mesh");
    mesh_vertices_ += size.vertices;
    mesh_triangles_ += size.triangles;
    over(mesh_vertices_, kMaxFragmentMeshVertices, "vertices",
         " in the fragment's meshes up to here");
    over(mesh_triangles_, kMaxFragmentMeshTriangles, "triangles",
         " in the fragment's meshes up to here");
  }

  // The texels MuJoCo makes of a <texture>. A built-in one (any `builtin` but "none") is made
  // from width and height even when it also names files: MuJoCo's compiler tries `builtin`
  // first (user_objects.cc, mjCTexture::Compile), so the files' sizes say nothing then. A cube or
  // skybox has six faces: built in, each is width x width (MuJoCo's convention for them;
  // height, if larger, is counted instead to stay on the safe side); from one image without a
  // gridsize, the image is every face.
  long textureTexels(const XMLElement* e, long width, long height, long file_texels) const {
    const char* type = e->Attribute("type");
    const bool cube = type && (std::strcmp(type, "cube") == 0 || std::strcmp(type, "skybox") == 0);
    const char* builtin = e->Attribute("builtin");
    const bool built_in = builtin && std::strcmp(builtin, "none") != 0;
    bool from_files = false;
    for (const char* attr : kFileAttributes) from_files = from_files || e->Attribute(attr);
    if (built_in || !from_files) {
      // Each face of a cube is width x width texels: bounded like one 2D texture.
      if (cube) checkSize(e, width, width, kMaxTexturePixels, "cube face");
      return cube ? 6 * width * std::max(width, height) : width * height;
    }
    const bool one_image = e->Attribute("file") && !e->Attribute("gridsize");
    return cube && one_image ? 6 * file_texels : file_texels;
  }

  // Adds what `e` costs to the fragment's total; refused once the total passes the budget.
  void spend(const XMLElement* e, long bytes) {
    spent_ += bytes;
    if (spent_ > kFragmentMemoryBudget)
      fail(e, "the fragment's height fields, textures and meshes need about " +
                  std::to_string(spent_ >> 20) + " MB up to here (this <" + e->Name() + "> " +
                  std::to_string(bytes >> 20) + " MB), more than the " +
                  std::to_string(kFragmentMemoryBudget >> 20) +
                  " MB a world fragment may use; make them smaller or fewer");
  }

  // Every number of a numeric attribute is finite, and positions and sizes are within the
  // world's scale: MuJoCo's compiler passes NaN sizes, and the simulation diverges on 1e308.
  void checkNumbers(const XMLElement* e) const {
    for (const tinyxml2::XMLAttribute* a = e->FirstAttribute(); a; a = a->Next()) {
      const std::string attr = a->Name();
      const bool length = attr == "pos" || attr == "size" || attr == "fromto" || attr == "scale";
      bool numeric = length;
      for (const char* n : kNumericAttributes) numeric = numeric || attr == n;
      if (!numeric) continue;
      const std::string place = at(e) + ", attribute " + attr;
      const char* p = a->Value();
      for (;;) {
        while (*p == ' ' || *p == '\t' || *p == '\n' || *p == '\r') ++p;
        if (*p == '\0') break;
        char* end = nullptr;
        const double v = std::strtod(p, &end);
        const std::string token(p, end > p ? end : p + std::strcspn(p, " \t\n\r"));
        if (end == p || !std::isfinite(v))
          throw InputError(file_, place, "'" + token + "' is not a finite number");
        if (length && std::abs(v) > kMaxFragmentCoordinate)
          throw InputError(file_, place,
                           token + " m is beyond the world's scale (at most " +
                               std::to_string(static_cast<long>(kMaxFragmentCoordinate)) +
                               " m from the origin)");
        p = end;
      }
    }
  }

  // rows x cols within [0, limit], without overflowing.
  void checkSize(const XMLElement* e, long rows, long cols, long limit,
                 const std::string& what) const {
    if (rows < 0 || cols < 0 || (cols > 0 && rows > limit / cols))
      fail(e, "a " + what + " of " + std::to_string(rows) + " x " + std::to_string(cols) +
                  " is more than the " + std::to_string(limit) + " samples allowed");
  }

  // A file named by the fragment: relative to the fragment's folder, a regular file of bounded
  // size, and (for height fields and textures) of bounded dimensions. Rewritten as absolute.
  // Returns the samples (height field) or texels (texture) it holds; a mesh's bytes are kept in
  // mesh_file_bytes_ (at least that much of it stays in memory).
  long resolveFile(XMLElement* e, const char* attr, const std::string& written) {
    std::filesystem::path p(written);
    if (p.is_relative()) p = dir_ / p;
    const std::string where = at(e) + " " + attr + "=\"" + written + "\"";
    std::string bytes;
    try {
      bytes = readInputFile(p.string(), kMaxAssetFileBytes, "mesh, height field or texture file");
    } catch (const InputError& err) {
      throw InputError(file_, where, err.problem() + " (" + p.string() + ")");
    }
    const std::string name = e->Name();
    long samples = 0;
    if (name == "mesh") {
      mesh_file_bytes_ = static_cast<long>(bytes.size());
      mesh_file_size_ = meshFileSize(p.filename().string(), bytes, kMaxMeshTriangles);
    }
    if (name == "hfield" || name == "texture") {
      long w = 0, h = 0;
      if (const auto size = pngSize(bytes); size[0] > 0) {
        w = size[0];
        h = size[1];
      } else if (bytes.size() >= 8) {
        // MuJoCo's own formats: int32 nrow, int32 ncol, then the floats (height field), or
        // int32 width, int32 height, then the RGB bytes (texture). The declared size is what
        // counts: MuJoCo checks it against the file's length in 32-bit arithmetic, which a
        // declared 65536 x 65536 texture wraps past.
        std::int32_t rows = 0, cols = 0;
        std::memcpy(&rows, bytes.data(), 4);
        std::memcpy(&cols, bytes.data() + 4, 4);
        w = rows;
        h = cols;
      }
      const long limit = name == "hfield" ? kMaxHeightFieldSamples : kMaxTexturePixels;
      if (w < 0 || h < 0 || (h > 0 && w > limit / h))
        throw InputError(file_, where,
                         "the file holds " + std::to_string(w) + " x " + std::to_string(h) +
                             " samples, more than the " + std::to_string(limit) + " allowed");
      samples = w * h;
    }
    e->SetAttribute(attr, std::filesystem::absolute(p).lexically_normal().c_str());
    return samples;
  }

  std::string file_;
  std::filesystem::path dir_;
  long elements_ = 0;
  long spent_ = 0;            // bytes the elements so far cost (kFragmentMemoryBudget)
  long mesh_file_bytes_ = 0;  // of the last mesh file read
  MeshSize mesh_file_size_;   // of the last mesh file read
  long mesh_vertices_ = 0;    // of the meshes so far (kMaxFragmentMeshVertices)
  long mesh_triangles_ = 0;   // of the meshes so far (kMaxFragmentMeshTriangles)
};

// The fragment parsed, or throws InputError.
void parseFragment(const std::filesystem::path& fragment, XMLDocument& src) {
  const std::string file = fragment.string();
  const std::string text = readInputFile(file, kMaxModelFileBytes, "MJCF fragment");
  if (src.Parse(text.data(), text.size()) != tinyxml2::XML_SUCCESS)
    throw InputError(file, "line " + std::to_string(src.ErrorLineNum()),
                     std::string("malformed XML: ") + src.ErrorName());
  const XMLElement* root = src.RootElement();
  if (!root || std::strcmp(root->Name(), "mujoco") != 0)
    throw InputError(file, root ? at(root) : std::string("line 1"),
                     "a world fragment is a <mujoco> element");
}

}  // namespace

std::vector<std::filesystem::path> worldFragmentFiles(const std::filesystem::path& fragment) {
  std::vector<std::filesystem::path> files;
  XMLDocument src;
  try {
    parseFragment(fragment, src);
  } catch (const InputError&) {
    return files;
  }
  const std::filesystem::path dir = std::filesystem::absolute(fragment).parent_path();
  std::vector<const XMLElement*> open = {src.RootElement()};
  while (!open.empty() && files.size() <= static_cast<std::size_t>(kMaxFragmentElements)) {
    const XMLElement* e = open.back();
    open.pop_back();
    for (const char* attr : kFileAttributes)
      if (const char* f = e->Attribute(attr)) {
        const std::filesystem::path p(f);
        files.push_back(p.is_relative() ? dir / p : p);
      }
    for (const XMLElement* c = e->FirstChildElement(); c; c = c->NextSiblingElement())
      open.push_back(c);
  }
  return files;
}

void addWorldFragment(XMLDocument& doc, XMLElement* mujoco, const std::filesystem::path& fragment) {
  XMLDocument src;
  parseFragment(fragment, src);
  XMLElement* root = src.RootElement();
  FragmentChecker checker(fragment);
  for (XMLElement* section = root->FirstChildElement(); section;
       section = section->NextSiblingElement())
    checker.checkSection(section);
  for (XMLElement* section = root->FirstChildElement(); section;
       section = section->NextSiblingElement())
    mujoco->InsertEndChild(section->DeepClone(&doc));
}

}  // namespace cosim
