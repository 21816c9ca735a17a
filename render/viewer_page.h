#pragma once
// viewer.html: a run's interactive 3D replay in one self-contained page. three.js and its orbit
// controls come from Debian's libjs-three (read when the page is written, embedded whole), the
// page's own code from render/viewer/ (compiled in), the run from render/viewer_data.h. The page
// loads nothing from the network.
#include <filesystem>
#include <string>

#include "run/record/run_record.h"
#include "sim/run_log.h"
#include "sim/scenario.h"
#include "sim/world_model.h"

namespace cosim {

// Where three.js is read from: $COSIM_THREE_DIR if set, else /usr/share/javascript/three
// (libjs-three). Files used: build/three.min.js, examples/js/controls/OrbitControls.js and
// examples/js/lines/ LineSegmentsGeometry.js, LineMaterial.js, LineSegments2.js (lines wider
// than WebGL's 1 px).
std::filesystem::path threeJsDirectory();

// three.min.js and OrbitControls.js, or the reason they cannot be had ("three.js not found:
// /usr/share/javascript/three/build/three.min.js is missing (Debian package libjs-three)").
struct ThreeJs {
  std::string three, orbit_controls, wide_lines;
  std::string missing;  // empty when both were read
};
ThreeJs loadThreeJs();

// The page: the template with its style, the scripts and the run's data (JSON) filled in.
std::string viewerPage(const std::string& data_json, const ThreeJs& three);

// Writes dir/viewer.html atomically. Returns "" when written, else why not (three.js missing);
// nothing is written then.
// record: as viewerData's.
std::string writeRunViewer(const std::filesystem::path& dir, const WorldModel& world,
                           const Scenario& scenario, const RunLog& log, const std::string& title,
                           const std::string& status, const RunRecord* record = nullptr);

}  // namespace cosim
