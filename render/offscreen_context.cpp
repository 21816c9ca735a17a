#include "render/offscreen_context.h"

#include <GL/osmesa.h>

#include <cstring>
#include <stdexcept>
#include <string>

namespace cosim {

int fontScaleForHeight(int height) {
  if (height >= 1000) return mjFONTSCALE_150;
  if (height >= 540) return mjFONTSCALE_100;
  return mjFONTSCALE_50;
}

OffscreenContext::OffscreenContext(const mjModel* m, int width, int height)
    : width_(width), height_(height) {
  if (width > m->vis.global.offwidth || height > m->vis.global.offheight)
    throw std::runtime_error("frame " + std::to_string(width) + "x" + std::to_string(height) +
                             " exceeds the model's off-screen buffer");
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 8, nullptr);
  if (!ctx) throw std::runtime_error("OSMesa: cannot create a context");
  osmesa_ = ctx;
  // The window-system buffer OSMesa renders to; MuJoCo draws into its own off-screen FBO.
  buffer_.resize(static_cast<std::size_t>(width) * height * 4);
  if (!OSMesaMakeCurrent(ctx, buffer_.data(), GL_UNSIGNED_BYTE, width, height)) {
    OSMesaDestroyContext(ctx);
    throw std::runtime_error("OSMesa: cannot make the context current");
  }
  mjr_defaultContext(&con_);
  mjr_makeContext(m, &con_, fontScaleForHeight(height));
  mjr_setBuffer(mjFB_OFFSCREEN, &con_);
  if (con_.currentBuffer != mjFB_OFFSCREEN)
    throw std::runtime_error("MuJoCo: the off-screen framebuffer is not available");
}

OffscreenContext::~OffscreenContext() {
  mjr_freeContext(&con_);
  if (osmesa_) OSMesaDestroyContext(static_cast<OSMesaContext>(osmesa_));
}

void OffscreenContext::readRgb(std::vector<std::uint8_t>& rgb) {
  const std::size_t row = static_cast<std::size_t>(width_) * 3;
  scratch_.resize(row * height_);
  rgb.resize(row * height_);
  mjr_readPixels(scratch_.data(), nullptr, viewport(), &con_);
  // OpenGL's rows start at the bottom; images start at the top.
  for (int y = 0; y < height_; ++y)
    std::memcpy(rgb.data() + y * row, scratch_.data() + (height_ - 1 - y) * row, row);
}

}  // namespace cosim
