// Where a stage's rounds run: the block lattice its reach needs, the ghost
// cutoff raised on the host to match, this process's view bounds and its
// partners (docs/design.md, "Parallel rules").
#pragma once

#include "reinforce_domain.h"
#include "reinforce_host_hooks.h"
#include "reinforce_schedule.h"
#include "reinforce_settings.h"

#include <vector>

namespace reinforce {

// The settings, the schedule, the ghost reach it needs (raised on the
// host) and this process's view bounds and partners.
struct Plan {
  Settings settings;
  Domain box, domain;
  BlockLattice lattice;
  std::vector<int> partners;
  double margin = 0;    // the view: atoms within this of a rebar sphere
};

// The ghost cutoff made at least `cutoff` on the host (logged when raised,
// naming the stage), or an ERROR when it is not finite.
void raise_ghost_cutoff(HostHooks &host, double cutoff, const char *stage);

// The lattice for a stage whose unit of work writes within `write` and
// reads within `read` of its particle, the ghost reach that needs (raised
// on the host, and logged when raised), this process's view bounds and its
// partners. `stage` names it in the log ("relocation", "regrowth").
void plan_rounds(HostHooks &host, double write, double read, const char *stage, Plan &plan);

}    // namespace reinforce
