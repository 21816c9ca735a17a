#pragma once
// Many thin lines (a team's flown trails) drawn as camera-facing ribbons in one OpenGL draw call,
// after MuJoCo's pass and into the same framebuffer (its depth buffer hides the parts behind
// obstacles). MuJoCo draws each mjvGeom with its own calls, twice when shadows are on: 32
// Crazyflies' 600 trail cylinders were most of a team frame's time, while the same segments as
// one array of triangles cost about as much as a single geom.
#include <mujoco/mujoco.h>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <vector>

namespace cosim {

class RibbonBatch {
 public:
  void clear() { segments_.clear(); }
  bool empty() const { return segments_.empty(); }
  std::size_t size() const { return segments_.size(); }

  // A line from a to b, `radius` (m) half-wide, in colour rgb (0..1) before shading.
  void add(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3f& rgb,
           double radius);

  // The triangles for a camera at `eye`: per segment, two quads side by side (a brighter middle
  // and darker edges, as a lit tube looks), lengthened by the radius at both ends so joints
  // between segments have no gaps. Three floats per vertex in `xyz`, three in `rgb`.
  void triangles(const Eigen::Vector3d& eye, std::vector<float>& xyz,
                 std::vector<float>& rgb) const;

  // The ribbons' shadows on the floor plane z = floor_z, cast along `light_dir` (pointing
  // down): dark flat ribbons, blended so that the floor under them is `darkness` darker, each
  // pixel once where shadows overlap. MuJoCo's shadow map showed the trails' height above the
  // floor this way; it does not see lines drawn after its pass.
  void shadowTriangles(const Eigen::Vector3d& light_dir, double floor_z,
                       std::vector<float>& xyz) const;

  // Draws the ribbons (and, with a light, their shadows first) into the current OpenGL context
  // with its projection and modelview matrices (the camera MuJoCo's mjr_render left set),
  // depth-tested, unlit; leaves the state as it found it.
  struct Shadow {
    bool on = false;
    Eigen::Vector3d light_dir = -Eigen::Vector3d::UnitZ();
    double floor_z = 0.0;
    float darkness = 0.4f;
  };
  // As MuJoCo's pass cast them: its first shadow-casting directional light, if the scene's
  // shadows are on.
  static Shadow shadowOf(const mjvScene& scene, double floor_z);
  void draw(const Eigen::Vector3d& eye, const Shadow& shadow);

 private:
  struct Segment {
    Eigen::Vector3d a, b;
    Eigen::Vector3f rgb;
    double radius;
  };
  std::vector<Segment> segments_;
  std::vector<float> xyz_, rgb_;  // kept between frames: no allocation per frame
};

}  // namespace cosim
