#include "render/scene_shapes.h"

#include <algorithm>
#include <limits>
#include <memory>

namespace cosim {

const char* shapeKindName(ShapeKind kind) {
  switch (kind) {
    case ShapeKind::Box:
      return "box";
    case ShapeKind::Cylinder:
      return "cylinder";
    case ShapeKind::Sphere:
      return "sphere";
    case ShapeKind::Capsule:
      return "capsule";
    case ShapeKind::Ellipsoid:
      return "ellipsoid";
  }
  return "box";
}

namespace {

struct DataDeleter {
  void operator()(mjData* d) const { mj_deleteData(d); }
};

// The model's kinematics at its initial configuration (qpos0, mocap bodies where their body
// elements put them): every geom's and body's world pose.
std::unique_ptr<mjData, DataDeleter> initialPoses(const mjModel* m) {
  std::unique_ptr<mjData, DataDeleter> d(mj_makeData(m));
  mj_kinematics(m, d.get());
  return d;
}

Eigen::Matrix3d rotationOf(const mjtNum* xmat) {
  Eigen::Matrix3d r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r(i, j) = xmat[3 * i + j];
  return r;
}

// A mesh geom's box: the extents of its vertices (in the geom's frame, as MuJoCo stores them).
Eigen::Vector3d meshExtents(const mjModel* m, int mesh) {
  Eigen::Vector3f lo = Eigen::Vector3f::Constant(std::numeric_limits<float>::infinity());
  Eigen::Vector3f hi = -lo;
  for (int k = 0; k < m->mesh_vertnum[mesh]; ++k) {
    const float* v = m->mesh_vert + 3 * (m->mesh_vertadr[mesh] + k);
    const Eigen::Vector3f p(v[0], v[1], v[2]);
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  if (m->mesh_vertnum[mesh] == 0) return Eigen::Vector3d::Zero();
  return (hi - lo).cast<double>();
}

// Geom g as a shape in world coordinates; false for planes, height fields and anything else that
// is not a solid of its own.
bool geomShape(const mjModel* m, const mjData* d, int g, SceneShape& s) {
  const mjtNum* size = m->geom_size + 3 * g;
  switch (m->geom_type[g]) {
    case mjGEOM_BOX:
      s.kind = ShapeKind::Box;
      s.size = 2.0 * Eigen::Vector3d(size[0], size[1], size[2]);
      break;
    case mjGEOM_CYLINDER:
      s.kind = ShapeKind::Cylinder;
      s.size = {2.0 * size[0], 2.0 * size[0], 2.0 * size[1]};
      break;
    case mjGEOM_CAPSULE:
      s.kind = ShapeKind::Capsule;
      s.size = {2.0 * size[0], 2.0 * size[0], 2.0 * size[1]};
      break;
    case mjGEOM_SPHERE:
      s.kind = ShapeKind::Sphere;
      s.size = Eigen::Vector3d::Constant(2.0 * size[0]);
      break;
    case mjGEOM_ELLIPSOID:
      s.kind = ShapeKind::Ellipsoid;
      s.size = 2.0 * Eigen::Vector3d(size[0], size[1], size[2]);
      break;
    case mjGEOM_MESH:
      s.kind = ShapeKind::Box;
      s.size = meshExtents(m, m->geom_dataid[g]);
      break;
    default:
      return false;
  }
  s.pos = Eigen::Vector3d(d->geom_xpos[3 * g], d->geom_xpos[3 * g + 1], d->geom_xpos[3 * g + 2]);
  s.rot = Eigen::Quaterniond(rotationOf(d->geom_xmat + 9 * g));
  const int mat = m->geom_matid[g];
  const float* rgba = mat >= 0 ? m->mat_rgba + 4 * mat : m->geom_rgba + 4 * g;
  s.rgba = Eigen::Vector4f(rgba[0], rgba[1], rgba[2], rgba[3]);
  return true;
}

// Shapes given in world coordinates, re-expressed in the frame (origin, rotation).
void toFrame(std::vector<SceneShape>& shapes, const Eigen::Vector3d& origin,
             const Eigen::Matrix3d& rotation) {
  const Eigen::Quaterniond inv(rotation.transpose());
  for (SceneShape& s : shapes) {
    s.pos = rotation.transpose() * (s.pos - origin);
    s.rot = inv * s.rot;
  }
}

}  // namespace

std::vector<SceneShape> staticWorldShapes(const WorldModel& world) {
  const mjModel* m = world.model();
  const auto d = initialPoses(m);
  std::vector<SceneShape> out;
  for (int g = 0; g < m->ngeom; ++g) {
    const int body = m->geom_bodyid[g];
    if (m->body_weldid[body] != 0 || m->body_mocapid[body] >= 0 || g == world.floorGeom()) continue;
    SceneShape s;
    if (geomShape(m, d.get(), g, s)) out.push_back(s);
  }
  return out;
}

std::vector<SceneShape> vehicleShapes(const WorldModel& world, std::size_t v) {
  const mjModel* m = world.model();
  const auto d = initialPoses(m);
  const VehicleHandles& h = world.vehicles().at(v);
  std::vector<SceneShape> out;
  for (int g : h.geoms) {
    SceneShape s;
    if (geomShape(m, d.get(), g, s)) out.push_back(s);
  }
  const Eigen::Vector3d origin(d->xpos[3 * h.body], d->xpos[3 * h.body + 1],
                               d->xpos[3 * h.body + 2]);
  toFrame(out, origin, rotationOf(d->xmat + 9 * h.body));
  if (h.drive.planar_root)
    for (SceneShape& s : out) s.pos.z() += origin.z();
  return out;
}

std::vector<SceneShape> movingObstacleShapes(const WorldModel& world, const std::string& name) {
  const mjModel* m = world.model();
  const int body = mj_name2id(m, mjOBJ_BODY, name.c_str());
  if (body < 0) return {};
  const auto d = initialPoses(m);
  std::vector<SceneShape> out;
  for (int g = 0; g < m->ngeom; ++g) {
    SceneShape s;
    if (m->geom_bodyid[g] == body && geomShape(m, d.get(), g, s)) out.push_back(s);
  }
  // The log has the obstacle's centre on the floor (z = 0): keep the body's height in the shapes.
  const Eigen::Vector3d origin(d->xpos[3 * body], d->xpos[3 * body + 1], 0.0);
  toFrame(out, origin, Eigen::Matrix3d::Identity());
  return out;
}

}  // namespace cosim
