#pragma once
// The replay page's own files (render/viewer/viewer.html.in, viewer.css, viewer_scene.js,
// viewer.js, viewer_controls.js), compiled in by CMake so that the program needs no source tree
// to write viewer.html.

namespace cosim {

const char* viewerTemplateHtml();
const char* viewerStyle();
const char* viewerSceneScript();
const char* viewerScript();
const char* viewerControlsScript();

}  // namespace cosim
