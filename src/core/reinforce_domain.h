// Where a process may place spheres: the box, its periodicity, the
// process's subdomain and view, the region and the walls; and the periodic
// geometry of it (reinforce_periodic.cpp). Shared by every stage.
#pragma once

#include "reinforce_boundaries.h"
#include "reinforce_vec3.h"

#include <functional>
#include <memory>
#include <vector>

namespace reinforce {

// Placement domain of one process.
struct Domain {
  Vec3 lo, hi;    // global box
  bool periodic[3] = {false, false, false};
  // Bounds of the spheres this process can see (its subdomain grown by the
  // ghost cutoff): a periodic image of a new sphere is added to the view
  // when its centre falls inside, as the host's own ghost images would be.
  Vec3 view_lo, view_hi;
  Vec3 sub_lo, sub_hi;    // this process's subdomain, [sub_lo, sub_hi)
  // Optional: true when the sphere of radius r about c (wrapped into the
  // box) lies wholly inside the user's region (the region's own surface
  // distance, as the host's region walls use it).
  std::function<bool(const Vec3 &c, double r)> region;
  // Optional: the walls of the host's wall fixes, which no placed or pushed
  // sphere may cross or overlap (the same for every process).
  std::shared_ptr<const Boundaries> walls;
};

// True when a sphere of radius r moved from `from` to c is inside the box
// in its non-periodic dimensions, inside the region and clear of the
// walls, each up to tol * r.
bool admissible(Vec3 from, Vec3 c, double r, const Domain &domain, double tol);

// The one copy of an atom that lies in the box (periodic images lie
// outside it), and whether x lies in this process's subdomain.
bool in_box(Vec3 x, const Domain &domain);
bool in_subdomain(Vec3 x, const Domain &domain);
// c wrapped into the box in its periodic dimensions, as the host wraps an
// atom that left it.
Vec3 wrapped_into_box(Vec3 c, const Domain &domain);
// c and its periodic images (shifted by one box length) that lie inside the
// process's view, as the host's ghosts would; with_centre false leaves c out.
std::vector<Vec3> images_in_view(Vec3 c, const Domain &domain, bool with_centre);

}    // namespace reinforce
