#include "render/html_report.h"

#include <sstream>
#include <stdexcept>

#include "core/atomic_file.h"
#include "core/display_text.h"
#include "core/json_flatten.h"
#include "render/metric_card.h"
#include "render/metric_groups.h"

namespace cosim {

std::string htmlEscape(const std::string& s) {
  std::string r;
  // A scenario's file name may hold control bytes and bytes that are not UTF-8 (the page says
  // utf-8): shown as \xNN.
  for (char c : displayText(s)) {
    switch (c) {
      case '&':
        r += "&amp;";
        break;
      case '<':
        r += "&lt;";
        break;
      case '>':
        r += "&gt;";
        break;
      case '"':
        r += "&quot;";
        break;
      case '\'':
        r += "&#39;";
        break;
      default:
        r += c;
    }
  }
  return r;
}

namespace {

// URL paths: the report's files are ours (no spaces or specials), but escape for attributes.
std::string attr(const std::string& s) {
  return htmlEscape(s);
}

const char* kStyle = R"(
body { font-family: "DejaVu Sans", Helvetica, Arial, sans-serif; margin: 20px auto; max-width: 1400px; padding: 0 16px; color: #1c1c22; }
h1 { font-size: 1.45em; margin-bottom: 4px; } h2 { font-size: 1.1em; margin: 24px 0 8px; border-bottom: 1px solid #ddd; }
h3 { font-size: 0.95em; margin: 0 0 4px; color: #333; }
p.sub { color: #555; margin-top: 0; }
video, img { width: 100%; border: 1px solid #ccc; background: #fff; }
.cards { display: flex; flex-wrap: wrap; gap: 10px; margin: 12px 0; }
.card { border: 1px solid #d8dbe0; border-radius: 6px; padding: 6px 14px; background: #f6f7f9; min-width: 120px; }
.card .k { font-size: 0.8em; color: #555; } .card .v { font-size: 1.25em; font-family: "DejaVu Sans Mono", monospace; }
.grid { display: grid; grid-template-columns: repeat(auto-fill, minmax(420px, 1fr)); gap: 14px; align-items: start; }
.tables { display: grid; grid-template-columns: repeat(auto-fill, minmax(300px, 1fr)); gap: 14px; align-items: start; }
.tables > div { min-width: 0; }
figure { margin: 0; }
figcaption { font-size: 0.85em; color: #444; }
table { border-collapse: collapse; font-size: 0.88em; width: 100%; }
td, th { border: 1px solid #ddd; padding: 2px 8px; text-align: left; overflow-wrap: anywhere; }
td.v { font-family: "DejaVu Sans Mono", monospace; text-align: right; }
tr:nth-child(even) { background: #f6f7f9; }
)";

// Counts every <img> and <video>; each reports load/loadeddata or error exactly once.
const char* kLoadCheck = R"(
(function () {
  var media = Array.prototype.slice.call(document.querySelectorAll('img, video'));
  var pending = media.length, failed = [];
  function finish() { document.body.setAttribute('data-media', failed.length ? 'failed: ' + failed.join(' ') : 'loaded'); }
  function settle(el, ok) {
    if (el.dataset.settled) return;
    el.dataset.settled = ok ? 'ok' : 'error';
    if (!ok) failed.push(el.getAttribute('src'));
    if (--pending === 0) finish();
  }
  document.body.setAttribute('data-media', 'pending');
  if (pending === 0) { finish(); return; }
  media.forEach(function (el) {
    if (el.tagName === 'IMG') {
      if (el.complete) { settle(el, el.naturalWidth > 0); return; }
      el.addEventListener('load', function () { settle(el, el.naturalWidth > 0); });
      el.addEventListener('error', function () { settle(el, false); });
    } else {
      if (el.readyState >= 2) { settle(el, true); return; }
      el.addEventListener('loadeddata', function () { settle(el, true); });
      el.addEventListener('error', function () { settle(el, false); });
      el.load();
    }
  });
})();
)";

// The videos (the first full width, the others in the grid) and the pictures, as a grid.
void writeMedia(std::ostringstream& h, const HtmlReport& r) {
  for (std::size_t i = 0; i < r.videos.size(); ++i) {
    if (i == 0) h << "<h2>Video</h2>\n";
    if (i == 1) h << "<div class=\"grid\">\n";
    const std::string& v = r.videos[i];
    h << "<figure><video src=\"" << attr(v) << "\" controls muted preload=\"auto\"></video>"
      << "<figcaption><a href=\"" << attr(v) << "\">" << htmlEscape(v)
      << "</a></figcaption></figure>\n";
  }
  if (r.videos.size() > 1) h << "</div>\n";
  if (r.figures.empty() && r.images.empty()) return;
  h << "<h2>Figures</h2>\n<div class=\"grid\">\n";
  for (const auto& i : r.images)
    h << "<figure><img src=\"" << attr(i) << "\" alt=\"" << attr(i) << "\"><figcaption><a href=\""
      << attr(i) << "\">" << htmlEscape(i) << "</a></figcaption></figure>\n";
  for (const auto& f : r.figures)
    h << "<figure><img src=\"" << attr(f) << ".png\" alt=\"" << attr(f) << "\">"
      << "<figcaption>" << htmlEscape(f) << " (<a href=\"" << attr(f)
      << ".png\">PNG</a>, <a href=\"" << attr(f) << ".svg\">SVG</a>)</figcaption></figure>\n";
  h << "</div>\n";
}

void writeVehicleTable(std::ostringstream& h, const VehicleMetricTable& t) {
  if (t.vehicles.empty()) return;
  h << "<h3 style=\"margin-top:14px\">Per vehicle</h3>\n<div style=\"overflow-x:auto\"><table>\n"
    << "<tr><th>metric</th>";
  for (const auto& v : t.vehicles) h << "<th>" << htmlEscape(v) << "</th>";
  h << "</tr>\n";
  for (std::size_t m = 0; m < t.metrics.size(); ++m) {
    h << "<tr><td>" << htmlEscape(t.metrics[m]) << "</td>";
    for (const auto& cell : t.cells[m])
      h << "<td class=\"v\">" << htmlEscape(cardValue(t.metrics[m], cell)) << "</td>";
    h << "</tr>\n";
  }
  h << "</table></div>\n";
}

}  // namespace

void writeHtmlReport(const std::filesystem::path& dir, const HtmlReport& r) {
  std::ostringstream h;
  h << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>"
    << htmlEscape(r.title) << "</title>\n<style>" << kStyle << "</style>\n</head>\n<body>\n<h1>"
    << htmlEscape(r.title) << "</h1>\n";
  if (!r.subtitle.empty()) h << "<p class=\"sub\">" << htmlEscape(r.subtitle) << "</p>\n";
  if (!r.viewer.empty())
    h << "<p><a href=\"" << attr(r.viewer) << "\">Open the interactive 3D replay ("
      << htmlEscape(r.viewer)
      << ")</a>: turn the camera, follow a vehicle, stop at any moment.</p>\n";
  const GroupedMetrics metrics = r.metrics.empty() ? GroupedMetrics{} : groupMetrics(r.metrics);
  if (!metrics.headline.empty()) {
    h << "<div class=\"cards\">\n";
    for (const auto& [k, v] : metrics.headline)
      h << "<div class=\"card\"><div class=\"k\">" << htmlEscape(k) << "</div><div class=\"v\">"
        << htmlEscape(cardValue(k, v)) << "</div></div>\n";
    h << "</div>\n";
  }
  writeMedia(h, r);
  if (!metrics.groups.empty() || !metrics.vehicles.vehicles.empty()) {
    h << "<h2>Metrics</h2>\n<p class=\"sub\">Rounded, with units; every digit is in "
         "metrics.json.</p>\n<div class=\"tables\">\n";
    for (const MetricGroup& g : metrics.groups) {
      h << "<div><h3>" << htmlEscape(g.title) << "</h3><table>\n";
      for (const auto& [k, v] : g.rows)
        h << "<tr><td>" << htmlEscape(k) << "</td><td class=\"v\">" << htmlEscape(cardValue(k, v))
          << "</td></tr>\n";
      h << "</table></div>\n";
    }
    h << "</div>\n";
    writeVehicleTable(h, metrics.vehicles);
  }
  h << "<script>" << kLoadCheck << "</script>\n</body>\n</html>\n";

  writeFileAtomically(dir / "index.html", h.str());
}

}  // namespace cosim
