// A stage of the work on the block schedule (docs/design.md, "Stages"):
// what its work is, in how many passes over the colours of the lattice,
// how far a unit of its work reads, and how it runs the work of the blocks
// a process owns in one round. The round runner (reinforce_round_runner.h) does the
// rest for any stage: rounds, the point-to-point exchange of the records,
// their application to the host's atoms and to every view. Relocation is
// the first stage.
#pragma once

#include "reinforce_particle.h"
#include "reinforce_round_records.h"

#include <cstddef>
#include <functional>
#include <vector>

namespace reinforce {

struct StageResult {
  std::vector<RoundRecord> records;    // what the work changed
  std::size_t done = 0;                // units of work done (the balance of the schedule)
};

class Stage {
public:
  virtual ~Stage() = default;
  // What the log calls it ("relocation", "regrowth").
  virtual const char *name() const = 0;
  // Passes over the colours: round = pass * colours + colour.
  virtual int passes() const = 0;
  // The pass of a particle that is this stage's work, or -1.
  virtual int pass_of(const Particle &p) const = 0;
  // Everything a unit of work reads lies within this of its particle.
  virtual double read_reach() const = 0;
  // Runs the work particles among `reads` for which `mine` is true;
  // `reads` holds every particle within read_reach() of them.
  virtual StageResult run(const std::vector<Particle> &reads,
                          const std::function<bool(const Particle &)> &mine) = 0;
};

}    // namespace reinforce
