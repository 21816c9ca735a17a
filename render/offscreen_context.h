#pragma once
// An OpenGL context with no display and no GPU: OSMesa renders into a memory buffer, and
// MuJoCo's renderer draws into its off-screen framebuffer inside that context.
#include <mujoco/mujoco.h>

#include <cstdint>
#include <vector>

namespace cosim {

// mjFONTSCALE_* for a frame height: text about 2 % of the frame height (readable, and the
// boxes leave the scene visible).
int fontScaleForHeight(int height);

class OffscreenContext {
 public:
  // The frame size must not exceed the model's <visual><global offwidth/offheight>.
  OffscreenContext(const mjModel* m, int width, int height);
  ~OffscreenContext();
  OffscreenContext(const OffscreenContext&) = delete;
  OffscreenContext& operator=(const OffscreenContext&) = delete;

  int width() const { return width_; }
  int height() const { return height_; }
  mjrContext* context() { return &con_; }
  mjrRect viewport() const { return {0, 0, width_, height_}; }

  // Reads the rendered frame as RGB rows from the top (image order), into `rgb`.
  void readRgb(std::vector<std::uint8_t>& rgb);

 private:
  void* osmesa_ = nullptr;  // OSMesaContext
  std::vector<unsigned char> buffer_;
  mjrContext con_;
  int width_, height_;
  std::vector<std::uint8_t> scratch_;
};

}  // namespace cosim
