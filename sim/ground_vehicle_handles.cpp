#include "sim/ground_vehicle_handles.h"

#include <Eigen/Geometry>
#include <cmath>

#include "core/input_error.h"

namespace cosim {

namespace {

// How far geom g reaches from its body's vertical axis (the body is the base or rides on it
// with its origin near the axis; wheels are the other case and their bound is conservative):
// exact for boxes (the farthest corner) and upright cylinders, the bounding sphere otherwise.
double horizontalReach(const mjModel* m, int g) {
  const Eigen::Vector3d pos(m->geom_pos[3 * g], m->geom_pos[3 * g + 1], m->geom_pos[3 * g + 2]);
  const Eigen::Quaterniond q(m->geom_quat[4 * g], m->geom_quat[4 * g + 1], m->geom_quat[4 * g + 2],
                             m->geom_quat[4 * g + 3]);
  const Eigen::Matrix3d R = q.normalized().toRotationMatrix();
  const mjtNum* size = m->geom_size + 3 * g;
  Eigen::Vector3d origin = pos;
  const int body = m->geom_bodyid[g];
  if (m->body_rootid[body] != body)  // a child body: add its offset from the base (one level)
    origin += Eigen::Vector3d(m->body_pos[3 * body], m->body_pos[3 * body + 1],
                              m->body_pos[3 * body + 2]);
  if (m->geom_type[g] == mjGEOM_BOX) {
    double reach = 0.0;
    for (int c = 0; c < 8; ++c) {
      const Eigen::Vector3d corner(c & 1 ? size[0] : -size[0], c & 2 ? size[1] : -size[1],
                                   c & 4 ? size[2] : -size[2]);
      reach = std::max(reach, (origin + R * corner).head<2>().norm());
    }
    return reach;
  }
  if (m->geom_type[g] == mjGEOM_CYLINDER && std::abs(R(2, 2)) > 1.0 - 1e-9)
    return origin.head<2>().norm() + size[0];
  return origin.head<2>().norm() + m->geom_rbound[g];
}

}  // namespace

void readGroundVehicleHandles(const mjModel* m, const VehicleSpec& v, VehicleHandles& h) {
  const std::string p = v.name + "/";
  const std::string file = v.model_file.string();
  h.kind = VehicleKind::GroundRobot;
  if (h.body < 0 || !readGroundDrive(m, v.name, h.drive))
    throw InputError(file, "<robot>", "the composed model lacks the ground robot's base or drive");
  const int root =
      mj_name2id(m, mjOBJ_JOINT, (p + (h.drive.planar_root ? "root_x" : "root")).c_str());
  if (root < 0) throw InputError(file, "<robot>", "the composed model lacks the base's root joint");
  h.qpos_adr = m->jnt_qposadr[root];
  h.qvel_adr = m->jnt_dofadr[root];
  if (h.drive.planar_root) {
    h.drive.planar_origin = {m->body_pos[3 * h.body], m->body_pos[3 * h.body + 1]};
    h.drive.start_yaw = v.yaw_deg * M_PI / 180.0;
  }
  QuadrotorParams& q = h.params;
  q.mass = m->body_subtreemass[h.body];
  q.gravity = -m->opt.gravity[2];
  // Horizontal bounding radius about the base origin, over the colliding geoms: what planners
  // inflate obstacles by and what clearance is measured from.
  q.radius = 0.0;
  for (int g = 0; g < m->ngeom; ++g) {
    if (m->body_rootid[m->geom_bodyid[g]] != h.body) continue;
    h.geoms.push_back(g);
    if (m->geom_contype[g] == 0 && m->geom_conaffinity[g] == 0) continue;
    q.radius = std::max(q.radius, horizontalReach(m, g));
  }
}

}  // namespace cosim

namespace cosim {

void setPlanarPose(mjData* d, const VehicleHandles& h, const Eigen::Vector2d& xy, double yaw) {
  mjtNum* q = d->qpos + h.qpos_adr;
  q[0] = xy.x() - h.drive.planar_origin.x();
  q[1] = xy.y() - h.drive.planar_origin.y();
  q[2] = yaw;
}

}  // namespace cosim
