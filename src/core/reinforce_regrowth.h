// Regrowth: room made for the targets the voids could not take, by moving
// the matrix near them (docs/design.md, "Regrowth"). The targets of a
// block left without a place (the seeds) are taken out; the zone's matrix
// (within `width` of them) settles onto the bars as hard spheres, then is
// compacted against them as soft spheres; then each seed, by id, goes back
// at its own radius where it fits alone; the others grow together while
// the zone relaxes, those it cannot hold given up (deleted), or (grow
// each) one by one, a seed that cannot fit deleted and the zone left as it
// was. The bars and everything beyond the zone are frozen, sizes never
// change, and no pair overlaps more than it did at the start.
// A target the relocation placed shrunk across thin bars is a seed too
// (grown with the others): its shrunk sphere gives way while it tries its
// own radius, and stays where that fails.
// Or (grow balance) the zone rebuilt: the seeds deleted by the volume
// balance, deepest first, the rest grown back with the zone's matrix
// shrunk and grown with them (every target placed shrunk is a seed then).
#pragma once

#include "reinforce_domain.h"
#include "reinforce_particle.h"
#include "reinforce_regrowth_policy.h"
#include "reinforce_settings.h"
#include "reinforce_round_records.h"

#include <cstdint>
#include <vector>

namespace reinforce {

struct RegrowthStats {
  std::int64_t seeds = 0;             // targets the regrowth took up
  std::int64_t regrown = 0;           // of them, put back at their own radius
  std::int64_t displaced = 0;         // of them, deleted first: centre inside a bar sphere
  std::int64_t deleted = 0;           // of them, deleted (displaced included)
  std::int64_t shrunk_seeds = 0;      // targets placed shrunk across thin bars, taken up again
  std::int64_t shrunk_regrown = 0;    // of them, put back at their own radius
  std::int64_t inexact = 0;     // moved spheres left overlapping (regrowth_policy::kRegrowthExact)
  std::int64_t moved = 0;       // matrix spheres moved
  std::int64_t sweeps = 0;      // projection sweeps over a block's zone
  double volume_regrown = 0;    // volume the regrown seeds added
  double max_overlap = 0;       // largest overlap of a regrown or moved sphere, / rmin
  double max_move = 0;          // largest displacement of a matrix sphere, / rmin
};

// How far the regrowth of one seed reaches from its centre: it moves
// spheres whose centres lie within `write` (before and after) and reads
// those within `read`, given the largest radius of a movable sphere
// (matrix_rmax) and of any sphere (largest_r).
struct RegrowthReach {
  double write = 0, read = 0;
};
RegrowthReach regrowth_reach(double width, double matrix_rmax, double largest_r);

// Regrows the zone of the seeds `seeds` (indices of Target particles of
// `reads`; `reads` holds every particle within regrowth_reach().read of
// them, and what else it holds is frozen). Other Target particles are vacant. Returns a Placed
// record for each seed kept, a Deleted one for each seed deleted (none for a shrunk one), and a
// Pushed one (the displacement) for each matrix sphere moved. The result depends only on the
// particles within reach of the seeds, not on their order.
std::vector<RoundRecord> regrow(const std::vector<Particle> &reads,
                                const std::vector<std::size_t> &seeds, double width,
                                const Settings &settings, const Domain &domain,
                                RegrowthStats &stats);

}    // namespace reinforce
