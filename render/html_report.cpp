#include "render/html_report.h"

#include <unistd.h>

#include <fstream>
#include <sstream>
#include <stdexcept>

#include "render/json_flatten.h"
#include "sim/temporary_name.h"

namespace cosim {

std::string htmlEscape(const std::string& s) {
  std::string r;
  for (char c : s) {
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
body { font-family: "DejaVu Sans", Helvetica, Arial, sans-serif; margin: 24px auto; max-width: 1320px; color: #1c1c22; }
h1 { font-size: 1.5em; margin-bottom: 4px; } h2 { font-size: 1.15em; margin-top: 28px; border-bottom: 1px solid #ddd; }
p.sub { color: #555; margin-top: 0; }
video, img { max-width: 100%; border: 1px solid #ccc; background: #fff; }
figure { display: inline-block; margin: 8px 12px 8px 0; vertical-align: top; max-width: 100%; }
figcaption { font-size: 0.9em; color: #444; }
table { border-collapse: collapse; font-size: 0.92em; }
td, th { border: 1px solid #ddd; padding: 3px 10px; text-align: left; }
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

}  // namespace

void writeHtmlReport(const std::filesystem::path& dir, const HtmlReport& r) {
  std::ostringstream h;
  h << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>"
    << htmlEscape(r.title) << "</title>\n<style>" << kStyle << "</style>\n</head>\n<body>\n<h1>"
    << htmlEscape(r.title) << "</h1>\n";
  if (!r.subtitle.empty()) h << "<p class=\"sub\">" << htmlEscape(r.subtitle) << "</p>\n";
  if (!r.videos.empty()) {
    h << "<h2>Video</h2>\n";
    for (const auto& v : r.videos)
      h << "<figure><video src=\"" << attr(v)
        << "\" controls muted preload=\"auto\" width=\"960\"></video>"
        << "<figcaption><a href=\"" << attr(v) << "\">" << htmlEscape(v)
        << "</a></figcaption></figure>\n";
  }
  if (!r.figures.empty() || !r.images.empty()) {
    h << "<h2>Figures</h2>\n";
    for (const auto& f : r.figures)
      h << "<figure><img src=\"" << attr(f) << ".png\" alt=\"" << attr(f) << "\" width=\"640\">"
        << "<figcaption>" << htmlEscape(f) << " (<a href=\"" << attr(f)
        << ".png\">PNG</a>, <a href=\"" << attr(f) << ".svg\">SVG</a>)</figcaption></figure>\n";
    for (const auto& i : r.images)
      h << "<figure><img src=\"" << attr(i) << "\" alt=\"" << attr(i)
        << "\" width=\"640\"><figcaption><a href=\"" << attr(i) << "\">" << htmlEscape(i)
        << "</a></figcaption></figure>\n";
  }
  if (!r.metrics_json.empty()) {
    h << "<h2>Metrics</h2>\n<table>\n<tr><th>metric</th><th>value</th></tr>\n";
    for (const auto& [k, v] : flattenJson(r.metrics_json))
      h << "<tr><td>" << htmlEscape(k) << "</td><td class=\"v\">" << htmlEscape(v)
        << "</td></tr>\n";
    h << "</table>\n";
  }
  h << "<script>" << kLoadCheck << "</script>\n</body>\n</html>\n";

  const std::filesystem::path target = dir / "index.html";
  const std::filesystem::path tmp = temporaryNameFor(target, ".part");
  {
    std::ofstream out(tmp);
    out << h.str();
    if (!out) throw std::runtime_error("cannot write " + tmp.string());
  }
  std::filesystem::rename(tmp, target);
}

}  // namespace cosim
