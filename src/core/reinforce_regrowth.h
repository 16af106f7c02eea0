// Regrowth: room made for the targets the voids could not take, or took
// only shrunk (the seeds), by growing the matrix around them again
// (docs/design.md, "Regrowth"). The count of seeds kept is decided first,
// from the volume the bars displace; then one zone (the matrix within its
// width of any seed, over the whole scene) shrinks and grows back with the
// kept seeds, every process moving the zone spheres it owns at once; the
// bars and everything beyond the zone stay, sizes never change, and no
// pair ends overlapping beyond what it overlapped at the start.
#pragma once

#include "reinforce_domain.h"
#include "reinforce_host_hooks.h"
#include "reinforce_relocation.h"
#include "reinforce_settings.h"

#include <cstdint>
#include <vector>

namespace reinforce {

struct RegrowthStats {
  std::int64_t seeds = 0;             // targets without a void the regrowth took up
  std::int64_t regrown = 0;           // of them, put back at their own radius
  std::int64_t displaced = 0;         // of them, deleted with the centre inside a bar
  std::int64_t deleted = 0;           // of them, deleted (displaced included)
  std::int64_t shrunk_seeds = 0;      // targets placed shrunk, taken up again
  std::int64_t shrunk_regrown = 0;    // of them, put back at their own radius
  std::int64_t inexact = 0;     // moved spheres left overlapping (regrowth_policy::kRegrowthExact)
  std::int64_t moved = 0;       // matrix spheres moved
  std::int64_t sweeps = 0;      // FIRE steps (the same on every process)
  double volume_regrown = 0;    // volume of the targets without a void put back
  double volume_unshrunk = 0;   // volume the shrunk targets put back got back
  double max_overlap = 0;       // largest overlap of a regrown or moved sphere, / rmin
  double max_move = 0;          // largest displacement of a matrix sphere, / rmin
  std::int64_t jammed = 0;      // 1 when the zone jammed or did not end clear (went back)
  double jam_scale = 0;         // the radii it reached then, a share of their own
};

// What the regrowth needs besides the host's atoms.
struct RegrowthInput {
  Settings settings;
  Domain domain;
  double width = 0;          // the zone: the matrix within this of a seed
  double matrix_rmin = 0, matrix_rmax = 0, largest = 0;
  std::vector<ShrunkTarget> shrunk;    // every process's targets placed shrunk
};

// How far the ghosts must reach for the regrowth: a moving sphere's
// neighbours, wherever both move within their caps, its bar, and the bars
// near a shrunk seed's old centre (within the relocation's `search` of
// where it was placed).
double regrowth_ghost_reach(double matrix_rmax, double largest, double search);

// Regrows the seeds: the host's pending atoms and `in.shrunk`, after the
// host's refresh with the ghosts reaching regrowth_ghost_reach. Moves and
// deletes the host's owned atoms. Collective.
void regrow(HostHooks &host, const RegrowthInput &in, RegrowthStats &stats);

}    // namespace reinforce
