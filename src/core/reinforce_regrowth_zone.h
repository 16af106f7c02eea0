// The bodies of a regrowth zone (docs/design.md, "Regrowth"): the seeds,
// the movable matrix spheres and the frozen spheres around them, with the
// pairs that can touch. Shared by the regrowth (reinforce_regrowth.cpp)
// and its soft-sphere relaxation (reinforce_soft_relaxation.cpp).
#pragma once

#include "reinforce_particle.h"
#include "reinforce_vec3.h"

#include <algorithm>
#include <cstdint>
#include <vector>

namespace reinforce {

struct Body {
  Vec3 x, x0;
  double R = 0;        // its own radius
  double scale = 1;    // its radius now, over R (below 1 only while a seed grows)
  double w = 0;        // mobility in the current growth: 1 at its seed, towards 0 at the edge
  double cap = 0;      // largest distance from x0
  std::int64_t id = 0;
  bool seed = false, movable = false, rebar = false, present = true;
  bool active = false;    // moves in the current growth
  bool placed = false;    // a seed put back
  // A seed placed shrunk by the relocation and its present shrunk sphere
  // (the same atom): each other's index, else -1.
  int twin = -1;
  double w_zone = 0;    // mobility in the settling: 1 - (distance to the nearest seed) / width
  int bar = -1;         // the nearest rebar sphere (a matrix sphere settles towards it)
};

struct Contact {
  int j = 0;
  // The pair's overlap at the start (pairs of matrix spheres): the most it
  // may overlap as they move. The packing's own overlaps (a packing settled
  // by DEM has one at every contact) are not the fix's: none gets worse,
  // and the spheres that have them can still move.
  double allowed = 0;
};

// The bodies of the zone of `seeds` (indices of Target particles of
// `reads`) in id order (then place): the seeds; the matrix spheres of the
// fix group within `width` of a seed, movable within their caps
// (regrowth_policy::kMoveShare); everything else frozen; other Target particles
// are vacant and left out. A seed that shares its id with a present
// sphere (a target the relocation placed shrunk) is its twin. Each movable
// matrix sphere knows its nearest rebar sphere.
std::vector<Body> zone_bodies(const std::vector<Particle> &reads,
                              const std::vector<std::size_t> &seeds, double width);

// For each movable body, the bodies it can touch within the caps of both
// (sorted), with the overlap the pair has at the start.
std::vector<std::vector<Contact>> zone_contacts(const std::vector<Body> &bodies);

// Whether b and o can touch, each within its cap of where it started.
inline bool can_touch(const Body &b, const Body &o)
{
  return norm(b.x0 - o.x0) < b.R + o.R + b.cap + o.cap;
}

// The overlap pair (b, o) may keep as they move (Contact::allowed): what
// two matrix spheres overlapped at the start, none with a seed.
inline double allowed_overlap(const Body &b, const Body &o)
{
  if (b.seed || o.seed) return 0;
  return std::max(0.0, b.R + o.R - norm(b.x0 - o.x0));
}

// Its radius now.
inline double radius(const Body &b)
{
  return b.R * b.scale;
}

// The direction from o to b at distance dist; for coincident centres one
// fixed by the ids.
inline Vec3 apart(const Body &b, const Body &o, double dist)
{
  if (dist > 1e-12 * (b.R + o.R)) return (1 / dist) * (b.x - o.x);
  return Vec3{b.id < o.id ? -1.0 : 1.0, 0, 0};
}

}    // namespace reinforce
