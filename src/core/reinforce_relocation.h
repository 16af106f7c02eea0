// The relocation stage's engine: the targets of one process's view
// relocated, its reach and what it reports (docs/design.md, "The
// relocation engine").
#pragma once

#include "reinforce_domain.h"
#include "reinforce_particle.h"
#include "reinforce_settings.h"
#include "reinforce_vec3.h"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

namespace reinforce {

// How far the relocation of one target reaches from the target's old centre:
// `write` bounds the centres of the spheres it moves or places (before and
// after), `read` the centres of every sphere it looks at. The ghost cutoff
// and the width of the blocks of the schedule follow from these.
struct Footprint {
  double write = 0, read = 0;
};
Footprint footprint(const Settings &s, double target_rmax, double largest_r);

// Totals of one relocation call (summed over the calls of a process, then
// combined over the processes as reinforce_totals.h says).
struct Stats {
  std::int64_t targets = 0, relocated = 0, unplaced = 0;
  std::int64_t displaced = 0;    // deleted without search: mostly inside the bars
  double volume_before = 0, volume_after = 0;
  double volume_removed = 0;      // volume of the targets not put back (deleted or kept)
  double max_overlap = 0;         // largest overlap of a relocated or pushed sphere, / rmin
  double max_kept_overlap = 0;    // largest overlap of a kept target with a present sphere, / rmin
  std::int64_t solves = 0;        // kernel calls
  std::int64_t pushed = 0;        // spheres pushed (counted once per target that pushed them)
  double max_push = 0;            // largest displacement of a pushed sphere in one call, / rmin
  std::int64_t sweeps = 0;        // rearrangement sweeps
  std::int64_t isolated = 0;      // unplaced with fewer than four spheres within `search`
  std::int64_t shrunk = 0;        // relocated with a radius below its own
};

// What became of one target.
enum class Outcome { Placed, Displaced, Unplaced };
struct TargetResult {
  std::size_t index = 0;    // the target's copy in the particle vector
  std::int64_t id = 0;
  Outcome outcome = Outcome::Unplaced;
  Vec3 x;          // Placed: final centre (the frame of the target's copy; may lie outside
                   // the box in periodic dims)
  double r = 0;    // Placed: final radius
};
// The accumulated displacement of a present sphere pushed to make room.
struct Push {
  std::int64_t id = 0;
  Vec3 dx;
};
// A target placed with a radius below its own: with the regrowth on, it
// takes it up again, at its own radius.
struct ShrunkTarget {
  std::int64_t id = 0;
  Vec3 x0;          // where it was (the frame of the target's copy)
  double r0 = 0;    // its own radius
};
struct Relocation {
  std::vector<TargetResult> targets;           // in the order they were relocated
  std::vector<Push> pushes;                    // increasing id; none of the targets above
  std::vector<ShrunkTarget> placed_shrunk;     // the targets above (with the regrowth on)
};

// Relocates the Target particles for which `mine` is true (default: the
// owned ones), in increasing id order (size keep: largest first, then by
// id). Particles with role Target are
// vacant, all others present. A relocated sphere is present for the targets
// after it. With keep_unplaced, a target that found no place stays where it
// is, present and never pushed.
Relocation relocate_targets(const std::vector<Particle> &particles, const Settings &settings,
                            const Domain &domain, bool keep_unplaced, Stats &stats,
                            const std::function<bool(const Particle &)> &mine = nullptr);

}    // namespace reinforce
