#include "render/viewer_page.h"

#include <cstdlib>
#include <fstream>
#include <sstream>

#include "core/atomic_file.h"
#include "render/viewer_assets.h"
#include "render/viewer_data.h"

namespace cosim {

namespace {

bool readWhole(const std::filesystem::path& p, std::string& out) {
  std::ifstream in(p, std::ios::binary);
  if (!in) return false;
  std::ostringstream s;
  s << in.rdbuf();
  out = s.str();
  return static_cast<bool>(in) || in.eof();
}

// Replaces the one placeholder `key` of the template by `value`.
void fill(std::string& page, const std::string& key, const std::string& value) {
  const auto at = page.find(key);
  if (at != std::string::npos) page.replace(at, key.size(), value);
}

// JSON text made safe inside <script type="application/json">: the HTML parser reads a script's
// text looking for "</script" and, after "<!--", for "<script" (which enters its double-escaped
// state, where "</script>" no longer ends the element: the page went dead). "<", ">" and "&"
// written as \u003c, \u003e and \u0026 leave it nothing to find; U+2028 and U+2029 (line
// separators to older JavaScript) as \u2028 and \u2029. JSON's own syntax uses none of these
// characters, so they occur only inside strings, where the escapes mean the same characters.
std::string scriptSafeJson(const std::string& json) {
  std::string out;
  out.reserve(json.size());
  for (std::size_t i = 0; i < json.size(); ++i) {
    const char c = json[i];
    if (c == '<')
      out += "\\u003c";
    else if (c == '>')
      out += "\\u003e";
    else if (c == '&')
      out += "\\u0026";
    else if (c == '\xe2' && i + 2 < json.size() && json[i + 1] == '\x80' &&
             (json[i + 2] == '\xa8' || json[i + 2] == '\xa9')) {
      out += json[i + 2] == '\xa8' ? "\\u2028" : "\\u2029";
      i += 2;
    } else {
      out += c;
    }
  }
  return out;
}

}  // namespace

std::filesystem::path threeJsDirectory() {
  if (const char* dir = std::getenv("COSIM_THREE_DIR"); dir && *dir) return dir;
  return "/usr/share/javascript/three";
}

ThreeJs loadThreeJs() {
  ThreeJs t;
  const std::filesystem::path dir = threeJsDirectory();
  const std::filesystem::path three = dir / "build" / "three.min.js";
  const std::filesystem::path orbit = dir / "examples" / "js" / "controls" / "OrbitControls.js";
  if (!readWhole(three, t.three))
    t.missing =
        "three.js not found: " + three.string() + " is missing (Debian package libjs-three)";
  else if (!readWhole(orbit, t.orbit_controls))
    t.missing =
        "three.js not found: " + orbit.string() + " is missing (Debian package libjs-three)";
  else {
    // Wide lines (WebGL draws GL lines 1 px wide whatever is asked): three.js's LineSegments2.
    for (const char* name : {"LineSegmentsGeometry.js", "LineMaterial.js", "LineSegments2.js"}) {
      std::string text;
      const std::filesystem::path file = dir / "examples" / "js" / "lines" / name;
      if (!readWhole(file, text)) {
        t.missing =
            "three.js not found: " + file.string() + " is missing (Debian package libjs-three)";
        return t;
      }
      t.wide_lines += text + "\n";
    }
  }
  if (!t.missing.empty()) return t;
  if (t.three.find("</script") != std::string::npos ||
      t.orbit_controls.find("</script") != std::string::npos ||
      t.wide_lines.find("</script") != std::string::npos)
    t.missing = "three.js at " + dir.string() + " contains </script> and cannot be embedded";
  return t;
}

std::string viewerPage(const std::string& data_json, const ThreeJs& three) {
  std::string page = viewerTemplateHtml();
  // Filled in this order: no value can carry a later placeholder into the page.
  fill(page, "/*@STYLE@*/", viewerStyle());
  fill(page, "/*@THREE@*/", three.three);
  fill(page, "/*@ORBIT_CONTROLS@*/", three.orbit_controls);
  fill(page, "/*@WIDE_LINES@*/", three.wide_lines);
  fill(page, "/*@VIEWER_SCENE@*/", viewerSceneScript());
  fill(page, "/*@VIEWER@*/", viewerScript());
  fill(page, "/*@VIEWER_CONTROLS@*/", viewerControlsScript());
  fill(page, "/*@RUN_DATA@*/", scriptSafeJson(data_json));
  return page;
}

std::string writeRunViewer(const std::filesystem::path& dir, const WorldModel& world,
                           const Scenario& scenario, const RunLog& log, const std::string& title,
                           const std::string& status, const RunRecord* record) {
  const ThreeJs three = loadThreeJs();
  if (!three.missing.empty()) return three.missing;
  const nlohmann::json data = viewerData(world, scenario, log, title, status, record);
  // Names from the scenario may hold bytes that are not UTF-8: replaced, not fatal.
  const std::string json = data.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  writeFileAtomically(dir / "viewer.html", viewerPage(json, three));
  return "";
}

}  // namespace cosim
