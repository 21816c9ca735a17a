#pragma once
// index.html for a run (or a sweep): its videos, images and figures with their metrics as a
// table, in one self-contained page that opens from the file system. A script in the page
// marks <body data-media="loaded"> once every image and video has loaded (or
// "failed: <files>"), so a headless browser can check the page.
#include <filesystem>
#include <string>
#include <vector>

#include "core/json_flatten.h"

namespace cosim {

struct HtmlReport {
  std::string title;
  std::string subtitle;             // one line under the title (e.g. the run's status)
  std::vector<std::string> videos;  // paths relative to the report
  std::vector<std::string> images;  // PNGs shown as they are (e.g. final.png)
  std::vector<std::string>
      figures;       // base paths relative to the report: <base>.png is shown, <base>.svg linked
  FlatJson metrics;  // metrics.json flattened (core/json_flatten.h), shown as tables

  std::string viewer;  // the 3D replay page, linked under the subtitle (may be empty)
};

// Writes dir/index.html atomically.
void writeHtmlReport(const std::filesystem::path& dir, const HtmlReport& report);

// Escapes &, <, >, " and ' for HTML text and attributes; control bytes and bytes that are not
// UTF-8 become the text \xNN (core/display_text.h).
std::string htmlEscape(const std::string& s);

}  // namespace cosim
