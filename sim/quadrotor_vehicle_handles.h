#pragma once
// Where a quadrotor lives in the compiled model, and what it is: its free joint, geoms and
// bounding radius, and its airframe read off the model (mass, inertia, rotor sites and spins, the
// rotor constants of <custom>, its separation ellipsoid). The conventions are those of models/
// (see models/quad_1500g.xml).
#include "sim/world_model.h"

namespace cosim {

// Fills h (h.name and h.body already set). Throws InputError naming the model file for a model
// that breaks the conventions: no free joint "root", rotor sites or constants missing or out of
// range.
void readQuadrotorHandles(const mjModel* m, const VehicleSpec& v, VehicleHandles& h);

}  // namespace cosim
