#include "render/ribbon_batch.h"

#include <GL/gl.h>

#include <algorithm>
#include <cmath>

namespace cosim {

namespace {
// A line's middle shows its colour exactly (the colour the figures and viewer.html draw it in:
// the run's visual language, render/overlay_palette.h), its edges a little darker, as a tube
// lit from the front looks.
constexpr float kMiddleShade = 1.0f;
constexpr float kEdgeShade = 0.78f;

void push(std::vector<float>& out, const Eigen::Vector3d& p) {
  out.push_back(static_cast<float>(p.x()));
  out.push_back(static_cast<float>(p.y()));
  out.push_back(static_cast<float>(p.z()));
}

void push(std::vector<float>& out, const Eigen::Vector3f& c, float shade) {
  for (int k = 0; k < 3; ++k) out.push_back(std::min(1.0f, c[k] * shade));
}
}  // namespace

void RibbonBatch::add(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                      const Eigen::Vector3f& rgb, double radius) {
  if ((b - a).norm() < 1e-9 || !(radius > 0.0)) return;
  segments_.push_back({a, b, rgb, radius});
}

void RibbonBatch::triangles(const Eigen::Vector3d& eye, std::vector<float>& xyz,
                            std::vector<float>& rgb) const {
  xyz.clear();
  rgb.clear();
  xyz.reserve(segments_.size() * 36);
  rgb.reserve(segments_.size() * 36);
  for (const Segment& s : segments_) {
    const Eigen::Vector3d d = (s.b - s.a).normalized();
    Eigen::Vector3d side = d.cross(eye - 0.5 * (s.a + s.b));
    // Seen end on, any direction across the line will do (the ribbon covers a dot).
    if (side.norm() < 1e-12) side = d.unitOrthogonal();
    side = side.normalized() * s.radius;
    const Eigen::Vector3d a = s.a - s.radius * d, b = s.b + s.radius * d;
    // Two quads, [edge, middle] on either side: 4 triangles.
    for (const double sign : {-1.0, 1.0}) {
      const Eigen::Vector3d ae = a + sign * side, be = b + sign * side;
      const Eigen::Vector3d* p[6] = {&ae, &a, &b, &ae, &b, &be};
      const bool middle[6] = {false, true, true, false, true, false};
      for (int k = 0; k < 6; ++k) {
        push(xyz, *p[k]);
        push(rgb, s.rgb, middle[k] ? kMiddleShade : kEdgeShade);
      }
    }
  }
}

void RibbonBatch::shadowTriangles(const Eigen::Vector3d& light_dir, double floor_z,
                                  std::vector<float>& xyz) const {
  xyz.clear();
  if (!(light_dir.z() < -1e-6)) return;  // a light from below or level casts none on the floor
  xyz.reserve(segments_.size() * 18);
  const auto onFloor = [&](const Eigen::Vector3d& p) {
    return Eigen::Vector3d(p + light_dir * ((floor_z - p.z()) / light_dir.z()));
  };
  for (const Segment& s : segments_) {
    if (s.a.z() < floor_z && s.b.z() < floor_z) continue;
    Eigen::Vector3d a = onFloor(s.a), b = onFloor(s.b);
    // Lifted a tenth of a line width: above the floor in the depth test, not visibly.
    a.z() = b.z() = floor_z + 0.1 * s.radius;
    Eigen::Vector3d d = b - a;
    d.z() = 0.0;
    // A vertical segment's shadow is a dot: any direction across will do.
    d = d.norm() > 1e-9 ? Eigen::Vector3d(d.normalized()) : Eigen::Vector3d::UnitX();
    const Eigen::Vector3d side = s.radius * Eigen::Vector3d(-d.y(), d.x(), 0.0);
    a -= s.radius * d;
    b += s.radius * d;
    const Eigen::Vector3d corners[6] = {a - side, a + side, b + side, a - side, b + side, b - side};
    for (const Eigen::Vector3d& p : corners) push(xyz, p);
  }
}

RibbonBatch::Shadow RibbonBatch::shadowOf(const mjvScene& scene, double floor_z) {
  Shadow shadow;
  shadow.floor_z = floor_z;
  for (int i = 0; i < scene.nlight && !shadow.on; ++i)
    if (scene.lights[i].castshadow && scene.lights[i].directional) {
      shadow.on = scene.flags[mjRND_SHADOW] != 0;
      const float* d = scene.lights[i].dir;
      shadow.light_dir = Eigen::Vector3d(d[0], d[1], d[2]).normalized();
    }
  return shadow;
}

void RibbonBatch::draw(const Eigen::Vector3d& eye, const Shadow& shadow) {
  if (segments_.empty()) return;
  glPushAttrib(GL_ENABLE_BIT | GL_CURRENT_BIT | GL_LIGHTING_BIT | GL_POLYGON_BIT |
               GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  glPushClientAttrib(GL_CLIENT_VERTEX_ARRAY_BIT);
  glDisable(GL_LIGHTING);
  glDisable(GL_TEXTURE_2D);
  glDisable(GL_CULL_FACE);
  glEnable(GL_DEPTH_TEST);
  glShadeModel(GL_SMOOTH);
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  glEnableClientState(GL_VERTEX_ARRAY);
  glDisableClientState(GL_NORMAL_ARRAY);
  glDisableClientState(GL_TEXTURE_COORD_ARRAY);
  if (shadow.on) {
    shadowTriangles(shadow.light_dir, shadow.floor_z, xyz_);
    // Blended black, each pixel once (the stencil counts), not hiding anything drawn later.
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glDepthMask(GL_FALSE);
    glEnable(GL_STENCIL_TEST);
    glClearStencil(0);
    glClear(GL_STENCIL_BUFFER_BIT);
    glStencilFunc(GL_EQUAL, 0, 0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, GL_INCR);
    glDisableClientState(GL_COLOR_ARRAY);
    glColor4f(0.0f, 0.0f, 0.0f, shadow.darkness);
    glVertexPointer(3, GL_FLOAT, 0, xyz_.data());
    glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(xyz_.size() / 3));
    glDisable(GL_STENCIL_TEST);
    glDepthMask(GL_TRUE);
  }
  glDisable(GL_BLEND);
  triangles(eye, xyz_, rgb_);
  glEnableClientState(GL_COLOR_ARRAY);
  glVertexPointer(3, GL_FLOAT, 0, xyz_.data());
  glColorPointer(3, GL_FLOAT, 0, rgb_.data());
  glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(xyz_.size() / 3));
  glPopClientAttrib();
  glPopAttrib();
}

}  // namespace cosim
