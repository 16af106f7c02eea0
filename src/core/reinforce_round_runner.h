// The rounds of the block schedule for one stage (docs/design.md, "Parallel
// rules"): each process runs the work of the blocks whose centres it owns,
// round after round, and sends what changed to its partner processes, which
// apply it to their views; the owners apply it to the host's atoms.
#pragma once

#include "reinforce_domain.h"
#include "reinforce_host_hooks.h"
#include "reinforce_particle.h"
#include "reinforce_schedule.h"
#include "reinforce_stage.h"

#include <vector>

namespace reinforce {

// Where the rounds run: the lattice, the global box, this process's view
// bounds, and the processes it exchanges records with (exchange_partners).
struct RoundPlan {
  BlockLattice lattice;
  Domain box, domain;
  std::vector<int> partners;
};

// What the rounds of a stage did, over all processes.
struct RoundsDone {
  int rounds = 0;        // rounds that had work
  double blocks = 0;     // blocks with work, summed over the rounds
  double busiest = 0;    // the busiest process's work, summed over the rounds
  double processes = 0;
};

// Runs `stage` over `view` (this process's particles, `local` their host
// indices in `a`), applying every round's records to the host's atoms and
// collecting the atoms to delete in `doomed` (the caller removes them).
// Collective.
RoundsDone run_rounds(HostHooks &host, Stage &stage, const RoundPlan &plan,
                      std::vector<Particle> view, const std::vector<int> &local,
                      const AtomArrays &a, std::vector<int> &doomed);

// The processes whose round results this one needs, and which need its
// own (see reinforce_round_runner.cpp); ascending, this process among them.
std::vector<int> exchange_partners(HostHooks &host, const Domain &domain, double beyond,
                                   double write, double seen);

// Element-wise sum (or max) over the processes of vectors of one length,
// by one gather.
std::vector<double> reduce_all(HostHooks &host, const std::vector<double> &mine, bool take_max);

}    // namespace reinforce
