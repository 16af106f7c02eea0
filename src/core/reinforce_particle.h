// The spheres the engine works on: one process's view of an atom, and the
// one definition of an overlap (docs/design.md, "Words"). Shared by every
// stage.
#pragma once

#include "reinforce_vec3.h"

#include <algorithm>
#include <cstdint>

namespace reinforce {

enum class Role : unsigned char {
  Rebar,     // never moved, always present
  Matrix,    // present, may be a neighbour of a relocated sphere
  Target,    // vacant: waiting for (or owned elsewhere and waiting for) a new place
};

// One sphere of a process's view: an owned atom or a ghost (a copy of an atom
// owned elsewhere, or a periodic image). Copies of one atom share its id.
struct Particle {
  Vec3 x;
  double r = 0;
  std::int64_t id = 0;
  Role role = Role::Matrix;
  bool owned = false;
  // A present matrix sphere that rearrangement may push: in the fix group,
  // not a kept target. Atoms outside the fix group are obstacles only.
  bool pushable = true;
  // In the rebar of another reinforce/invert fix: an obstacle that never
  // moves, not a bar of this one; its overlaps are not the packing's.
  bool other_rebar = false;
};

// True when spheres (a, ra) and (b, rb) overlap by more than tol * min(ra, rb).
inline bool spheres_overlap(Vec3 a, double ra, Vec3 b, double rb, double tol)
{
  return ra + rb - norm(a - b) > tol * std::min(ra, rb);
}

}    // namespace reinforce
