#pragma once
// The roadmap of a dense quadrotor team: a lattice finer than the separation ellipsoid, so that
// starts and goals closer than the team grid's cells (team_grid.h: sqrt(2) separations) still
// land on distinct vertices, with conflicts defined by the ellipsoids themselves
// (ellipsoid_conflict.h) instead of by one agent per cell. As Hoenig et al. ("Trajectory
// planning for quadrotor swarms", T-RO 2018, §IV) choose their roadmap independently of the
// robots' ellipsoids, the pitch here comes from the starts and goals: the coarsest of
// separation / k ellipsoid semi-axes per axis, k = 1 .. 4, anchored at the first agent's start or
// centred in the bounds, on which every start and goal lies in a free cell and each agent's
// first move (start to its vertex) and last (vertex to goal), flown all together, keep every
// pair the separation apart. The coarsest is taken because the step time grows with the pitch
// less than the number of steps shrinks.
//
// A team whose starts and goals all lie at one height (as Crazyswarm's usually do) is planned in
// that plane: every other layer of the lattice is blocked, so no vehicle flies through another's
// downwash (allow_planar false: every layer open, for a team the plane cannot hold). Measured on
// the bundled 0.5 m swap with the layers open (1.5 ellipsoids, 0.9 m apart vertically): a cf2
// passing under another sagged 0.17 m and was pushed 0.21 m sideways (the wake reaches far:
// sim/downwash.h), closing a horizontal pair to 0.91 ellipsoids.
#include <Eigen/Core>
#include <vector>

#include "planning/mapf/mapf_graph.h"
#include "planning/team/separation_ellipsoid.h"
#include "planning/team/team_grid.h"
#include "planning/world/world.h"

namespace cosim {

struct DenseRoadmap {
  TeamGrid grid;
  MapfGraph graph;                         // 6-connected over the free cells
  std::vector<Eigen::Vector3d> positions;  // per vertex, its cell's centre
  std::vector<int> starts, goals;          // per agent, a vertex
  int refinement = 1;                      // k: the pitch is separation / k semi-axes
  bool planar = false;                     // only the starts' and goals' layer is open
};

// Throws InputError (place "vehicles[i].start" / ".goal") when two starts or two goals are
// closer than the separation, or no lattice holds them all (naming the first start or goal that
// fails on the finest).
DenseRoadmap denseRoadmap(const World& world, const std::vector<Eigen::Vector3d>& starts,
                          const std::vector<Eigen::Vector3d>& goals,
                          const SeparationEllipsoid& ellipsoid, double separation, double inflation,
                          bool allow_planar = true);

}  // namespace cosim
