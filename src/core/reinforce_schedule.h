// The schedule of the relocation work (docs/design.md, "Parallel rules"):
// a lattice of blocks over the box, fixed by the box and the footprint of
// one relocation, never by the processor grid. Blocks are coloured by
// parity; the blocks of one colour are at least one block apart, so they
// can be relocated at once, each by one process (the owner of the block's
// centre), and every process count follows the same schedule.
#pragma once

#include "reinforce_vec3.h"

namespace reinforce {

struct BlockLattice {
  Vec3 lo, width;
  int count[3] = {1, 1, 1};
  int colours[3] = {1, 1, 1};

  int rounds() const { return colours[0] * colours[1] * colours[2]; }
  // The block of a point of the box (clamped to the lattice) and its colour.
  void block_of(Vec3 x, int b[3]) const;
  int colour_of(Vec3 x) const;
  Vec3 centre_of(Vec3 x) const;
  // How far beyond the box [sub_lo, sub_hi) the blocks whose centres lie
  // in it reach, the largest over the dimensions: how far beyond its
  // subdomain a process may have to work (0 where the subdomain's faces lie
  // on block faces; at most half a block).
  double reach_beyond(Vec3 sub_lo, Vec3 sub_hi) const;
};

// Blocks at least min_width wide (as many as fit). A periodic dimension
// gets an even count (parity colouring must hold across the boundary) or a
// single block; a dimension with one block needs one colour.
BlockLattice make_block_lattice(Vec3 lo, Vec3 hi, const bool periodic[3], double min_width);

}    // namespace reinforce
