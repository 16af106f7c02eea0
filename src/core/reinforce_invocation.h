// One invocation of fix reinforce/invert, shared by the LAMMPS and LIGGGHTS
// adapters: they implement HostHooks with their own atoms and communication,
// and run_invocation does the rest (docs/design.md).
#pragma once

#include "reinforce_fix_options.h"
#include "reinforce_host_hooks.h"
#include "reinforce_totals.h"

namespace reinforce {

// Runs one invocation: radius range, ghost reach, one refresh, targets, the
// rounds of the block schedule (each round's results delivered to the
// atoms' owners and applied to the views of the processes that see them),
// deletions, totals
// and the log lines. Collective: every process calls it.
Totals run_invocation(HostHooks &host, const FixOptions &options);

}    // namespace reinforce
