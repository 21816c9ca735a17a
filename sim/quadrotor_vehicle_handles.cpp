#include "sim/quadrotor_vehicle_handles.h"

#include <algorithm>
#include <cmath>

#include "core/decimal_text.h"
#include "core/input_error.h"
#include "sim/airframe_file.h"

namespace cosim {

namespace {

// The value of the vehicle's <custom><numeric name="<prefix><name>"> (see models/quad_1500g.xml),
// which must be one finite number within [lo, hi].
double rotorConstant(const mjModel* m, const std::string& prefix, const char* name, double lo,
                     double hi, const std::string& file) {
  const int id = mj_name2id(m, mjOBJ_NUMERIC, (prefix + name).c_str());
  if (id < 0)
    throw InputError(file, "<custom>", std::string("needs <numeric name=\"") + name + "\">");
  const double v = m->numeric_data[m->numeric_adr[id]];
  if (m->numeric_size[id] != 1 || !std::isfinite(v) || v < lo || v > hi)
    throw InputError(file, std::string("<numeric name=\"") + name + "\">",
                     "must be one number in [" + tenSignificantDigits(lo) + ", " +
                         tenSignificantDigits(hi) + "]");
  return v;
}

}  // namespace

void readQuadrotorHandles(const mjModel* m, const VehicleSpec& v, VehicleHandles& h) {
  const std::string p = v.name + "/";
  const std::string file = v.model_file.string();
  const int joint = mj_name2id(m, mjOBJ_JOINT, (p + "root").c_str());
  if (h.body < 0 || joint < 0 || m->jnt_type[joint] != mjJNT_FREE)
    throw InputError(file, "<body name=\"base\">", "needs a free joint named \"root\"");
  h.qpos_adr = m->jnt_qposadr[joint];
  h.qvel_adr = m->jnt_dofadr[joint];
  QuadrotorParams& q = h.params;
  q.mass = m->body_subtreemass[h.body];
  q.inertia = Eigen::Vector3d(m->body_inertia[3 * h.body], m->body_inertia[3 * h.body + 1],
                              m->body_inertia[3 * h.body + 2]);
  q.gravity = -m->opt.gravity[2];
  // Rotor sites; spins and the moment constant from <custom> (no actuators: sim/ applies the
  // rotors' wrench itself, see models/quad_1500g.xml).
  const int spin_id = mj_name2id(m, mjOBJ_NUMERIC, (p + "rotor_spin").c_str());
  if (spin_id < 0 || m->numeric_size[spin_id] != 4)
    throw InputError(file, "<custom>",
                     "needs <numeric name=\"rotor_spin\"> with 4 values (+1 or -1)");
  for (int i = 0; i < 4; ++i) {
    const int site = mj_name2id(m, mjOBJ_SITE, (p + "rotor" + std::to_string(i)).c_str());
    if (site < 0 || m->site_bodyid[site] != h.body)
      throw InputError(file, "<body name=\"base\">", "needs sites rotor0..3 on the base");
    q.rotor_xy[i] = Eigen::Vector2d(m->site_pos[3 * site], m->site_pos[3 * site + 1]);
    q.rotor_z = m->site_pos[3 * site + 2];
    const double spin = m->numeric_data[m->numeric_adr[spin_id] + i];
    if (spin != 1.0 && spin != -1.0)
      throw InputError(file, "<numeric name=\"rotor_spin\">", "each value must be +1 or -1");
    q.spin[i] = spin;
  }
  q.torque_per_thrust = rotorConstant(m, p, "moment_constant", 0.0, 1.0, file);
  q.thrust_coefficient = rotorConstant(m, p, "thrust_coefficient", 1e-12, 1.0, file);
  q.min_rotor_speed = rotorConstant(m, p, "min_rotor_speed", 0.0, 1e5, file);
  q.max_rotor_speed = rotorConstant(m, p, "max_rotor_speed", 1.0, 1e5, file);
  if (q.max_rotor_speed <= q.min_rotor_speed)
    throw InputError(file, "<numeric name=\"max_rotor_speed\">", "must exceed min_rotor_speed");
  q.time_constant_up = rotorConstant(m, p, "time_constant_up", 1e-4, 10.0, file);
  q.time_constant_down = rotorConstant(m, p, "time_constant_down", 1e-4, 10.0, file);
  q.rotor_drag_coefficient = rotorConstant(m, p, "rotor_drag_coefficient", 0.0, 1.0, file);
  q.rolling_moment_coefficient = rotorConstant(m, p, "rolling_moment_coefficient", 0.0, 1.0, file);
  q.propeller_radius = rotorConstant(m, p, "propeller_radius", 1e-3, 10.0, file);
  q.zero_thrust_inflow = rotorConstant(m, p, "zero_thrust_inflow", 0.1, 1000.0, file);
  // Optional: the motor's steady-state speed over duty cycle times battery voltage.
  const int map = mj_name2id(m, mjOBJ_NUMERIC, (p + "motor_speed_map").c_str());
  if (map >= 0) {
    if (m->numeric_size[map] != 3)
      throw InputError(file, "<numeric name=\"motor_speed_map\">",
                       "needs 3 values: c0 (rad/s), c1 (rad/s/V), c2 (rad/s/V^2)");
    for (int i = 0; i < 3; ++i) q.motor_speed_map[i] = m->numeric_data[m->numeric_adr[map] + i];
    if (!q.motor_speed_map.allFinite() || !(q.motor_speed_map[1] > 0.0))
      throw InputError(file, "<numeric name=\"motor_speed_map\">",
                       "values must be finite, c1 positive");
  }
  const int sep = mj_name2id(m, mjOBJ_NUMERIC, (p + "separation").c_str());
  if (sep < 0 || m->numeric_size[sep] != 2 || !(m->numeric_data[m->numeric_adr[sep]] > 0) ||
      !(m->numeric_data[m->numeric_adr[sep] + 1] > 0))
    throw InputError(file, "<custom>",
                     "needs <numeric name=\"separation\" data=\"RADIUS HEIGHT\"> (m, both > 0)");
  q.motor_delay = 0.0;
  if (mj_name2id(m, mjOBJ_NUMERIC, (p + "motor_delay").c_str()) >= 0)
    q.motor_delay = rotorConstant(m, p, "motor_delay", 0.0, 1.0, file);
  applyAirframeFile(v.airframe, q);
  if (v.airframe.gyro_noise) h.gyro_noise = *v.airframe.gyro_noise;
  if (v.airframe.accel_noise) h.accel_noise = *v.airframe.accel_noise;
  q.separation_radius = m->numeric_data[m->numeric_adr[sep]];
  q.separation_height = m->numeric_data[m->numeric_adr[sep] + 1];
  q.min_thrust = q.thrust_coefficient * q.min_rotor_speed * q.min_rotor_speed;
  q.max_thrust = q.thrust_coefficient * q.max_rotor_speed * q.max_rotor_speed;
  // Bounding radius about the centre of mass, over every geom of the vehicle.
  q.radius = 0.0;
  for (int g = 0; g < m->ngeom; ++g) {
    if (m->body_rootid[m->geom_bodyid[g]] != h.body) continue;
    h.geoms.push_back(g);
    const Eigen::Vector3d pos(m->geom_pos[3 * g], m->geom_pos[3 * g + 1], m->geom_pos[3 * g + 2]);
    q.radius = std::max(q.radius, pos.norm() + m->geom_rbound[g]);
  }
}

}  // namespace cosim
