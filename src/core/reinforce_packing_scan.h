// Passes over a host's atoms or a process's view before the stages: the
// spheres near the bars, the targets, the overlaps the packing already has.
#pragma once

#include "reinforce_particle.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace reinforce {

// Indices (ascending) of the spheres in [0, n) whose surface comes within
// `margin` of a rebar sphere's surface, rebar spheres included. x[i] points
// at three doubles (the hosts' double **x). Cost: O(n) plus the work near
// the rebar, whatever the rebar radius.
std::vector<int> spheres_near_rebar(int n, const double *const *x, const double *radius,
                                    const unsigned char *is_rebar, double margin);

// Indices of the owned non-rebar particles that overlap a rebar particle.
std::vector<std::size_t> find_targets(const std::vector<Particle> &particles, double tol);

// Pairs of non-rebar particles that already overlap (by more than tol *
// min radius), each pair counted on exactly one process: by the owner of
// the lower id. `largest` gets the largest such overlap relative to rmin.
std::int64_t count_packing_overlaps(const std::vector<Particle> &particles, double tol, double rmin,
                                    double &largest);

}    // namespace reinforce
