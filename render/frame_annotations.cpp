#include "render/frame_annotations.h"

#include <algorithm>
#include <cstdio>

#include "render/overlay_palette.h"

namespace cosim {

namespace {
const Eigen::Vector3f kText{0.05f, 0.05f, 0.08f};
}

FrameAnnotations::FrameAnnotations(mjrContext* con, mjrRect viewport)
    : con_(con), viewport_(viewport), pad_(std::max(3, con->charHeight / 3)) {}

int FrameAnnotations::textWidth(const std::string& s) const {
  int w = 0;
  for (unsigned char c : s)
    w += c < 127 ? con_->charWidth[c] : con_->charWidth[static_cast<int>('?')];
  return w;
}

int FrameAnnotations::lineHeight() const {
  return con_->charHeight + pad_ / 2;
}

int FrameAnnotations::linesFitting(double fraction) const {
  return static_cast<int>((fraction * viewport_.height - 2 * pad_) / lineHeight());
}

void FrameAnnotations::box(int x, int y, int w, int h) {
  mjr_rectangle({x, y, w, h}, 1.0f, 1.0f, 1.0f, 0.78f);
}

void FrameAnnotations::text(const std::string& s, int x, int y, const Eigen::Vector3f& rgb) {
  // mjr_label centres its text in the rectangle; a rectangle exactly the text's width places
  // it left-aligned at x. Alpha 0: the panel behind it is already drawn.
  mjr_label({x, y, textWidth(s) + 2, con_->charHeight}, mjFONT_NORMAL, s.c_str(), 1, 1, 1, 0.0f,
            rgb.x(), rgb.y(), rgb.z(), con_);
}

mjrRect FrameAnnotations::stateBox(const std::vector<std::pair<std::string, std::string>>& lines) {
  int label_w = 0, value_w = 0;
  for (const auto& [l, v] : lines) {
    label_w = std::max(label_w, textWidth(l));
    value_w = std::max(value_w, textWidth(v));
  }
  const int gap = 2 * con_->charWidth[static_cast<int>('m')];
  const int w = label_w + gap + value_w + 2 * pad_;
  const int h = static_cast<int>(lines.size()) * lineHeight() + 2 * pad_;
  const int x = viewport_.left + pad_, top = viewport_.bottom + viewport_.height - pad_;
  box(x, top - h, w, h);
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const int y = top - pad_ - static_cast<int>(i + 1) * lineHeight();
    text(lines[i].first, x + pad_, y, {0.3f, 0.3f, 0.35f});
    text(lines[i].second, x + pad_ + label_w + gap, y, kText);
  }
  return {x, top - h, w, h};
}

mjrRect FrameAnnotations::legend(const std::vector<LegendEntry>& entries) {
  const int swatch = 2 * con_->charHeight;
  int label_w = 0;
  for (const auto& e : entries) label_w = std::max(label_w, textWidth(e.label));
  const int w = swatch + pad_ + label_w + 3 * pad_;
  const int h = static_cast<int>(entries.size()) * lineHeight() + 2 * pad_;
  const int x = viewport_.left + pad_, y0 = viewport_.bottom + pad_;
  box(x, y0, w, h);
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const int y = y0 + h - pad_ - static_cast<int>(i + 1) * lineHeight();
    const int sy = y + con_->charHeight / 3, sh = std::max(3, con_->charHeight / 3);
    const auto& stripes = entries[i].stripes;
    const int pieces = entries[i].gradient ? 8 : std::max<int>(1, stripes.size());
    for (int k = 0; k < pieces; ++k) {
      const Eigen::Vector3f c = entries[i].gradient ? errorColour((k + 0.5) / pieces)
                                : stripes.empty()   ? entries[i].colour
                                                    : stripes[k];
      const int x0 = x + pad_ + swatch * k / pieces, x1 = x + pad_ + swatch * (k + 1) / pieces;
      mjr_rectangle({x0, sy, x1 - x0, sh}, c.x(), c.y(), c.z(), 1.0f);
    }
    text(entries[i].label, x + 2 * pad_ + swatch, y, kText);
  }
  return {x, y0, w, h};
}

mjrRect FrameAnnotations::errorScale(double scale_max, const std::string& title, int slot,
                                     bool compact) {
  const int bar_w = std::max(60, viewport_.width / (compact ? 8 : 5));
  const int bar_h = std::max(6, con_->charHeight / 2);
  // Wide enough for the title too (the end labels stand half outside the bar).
  const int w =
      std::max(bar_w + 2 * con_->charWidth[static_cast<int>('0')], textWidth(title)) + 2 * pad_;
  const int h = 2 * lineHeight() + bar_h + 2 * pad_;
  const int x = viewport_.left + viewport_.width - pad_ - w,
            y = viewport_.bottom + pad_ + slot * (h + pad_);
  box(x, y, w, h);
  const int bx = x + (w - bar_w) / 2, by = y + pad_ + lineHeight();
  const int steps = 48;
  for (int i = 0; i < steps; ++i) {
    const Eigen::Vector3f c = errorColour((i + 0.5) / steps);
    const int x0 = bx + bar_w * i / steps, x1 = bx + bar_w * (i + 1) / steps;
    mjr_rectangle({x0, by, x1 - x0, bar_h}, c.x(), c.y(), c.z(), 1.0f);
  }
  char hi[32];
  std::snprintf(hi, sizeof hi, "%g", scale_max);
  const int ty = y + pad_ / 2;
  text("0", bx - textWidth("0") / 2, ty, kText);
  text(hi, bx + bar_w - textWidth(hi) / 2, ty, kText);
  text(title, x + (w - textWidth(title)) / 2, by + bar_h + pad_ / 2, kText);
  return {x, y, w, h};
}

}  // namespace cosim
