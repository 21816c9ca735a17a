#pragma once
// Which pairs of a team can come close within a window of time, from a spatial hash instead of
// all n (n - 1) / 2 pairs: the broad phase of the team's continuous-time check
// (team_trajectories.h). Each agent's sampled positions over the window are boxed in coordinates
// scaled by the team's largest separation semi-axes (x / radius, y / radius, z / height), where
// a pair's ellipsoidal distance is at least the Euclidean distance of its scaled positions; the
// box, grown by reach / 2 on every side, is entered into the cubic cells of side `reach` it
// overlaps. Two agents that come within `reach` of each other (ellipsoidal distance) at an
// instant of the window then have overlapping grown boxes, so they share a cell: no pair that
// can violate the separation is missed. 500 quadrotors spread over a room meet a few neighbours
// each, where all pairs are 124 750.
#include <Eigen/Core>
#include <cstdint>
#include <utility>
#include <vector>

namespace cosim {

// samples[i][s]: agent i's position at instant s. Pairs (i < j) whose boxes over instants
// [first, last] share a cell, sorted, each once.
std::vector<std::pair<int, int>> candidatePairs(
    const std::vector<std::vector<Eigen::Vector3d>>& samples, long first, long last,
    const Eigen::Vector3d& scale, double reach);

}  // namespace cosim
