// The regrowth's seeds and their count (docs/design.md, "Regrowth"): which
// targets it takes up, and how many of them it deletes, decided from the
// volume the bars displace before anything grows.
#pragma once

#include "reinforce_domain.h"
#include "reinforce_host_hooks.h"
#include "reinforce_regrowth_zone.h"
#include "reinforce_relocation.h"

#include <vector>

namespace reinforce {

// Every process's seeds, in id order: the targets left without a void
// (pending atoms) and those placed shrunk (`shrunk`, every process's),
// each measured by the owner of its atom against the rebar spheres it
// sees (within the ghost cutoff of its old centre): the depth of its old
// centre and its volume inside the bars. Collective.
std::vector<Seed> gather_seeds(HostHooks &host, const AtomArrays &a,
                               const std::vector<ShrunkTarget> &shrunk, const Domain &domain);

// The count, the same on every process: seeds deleted in order of depth
// (the deepest centre first, equal depths by id) while each brings the
// deleted volume (a shrunk seed's: what it lost) nearer `share` times the
// seeds' volume inside the bars; the rest are kept.
void count_kept(std::vector<Seed> &seeds, double share);

}    // namespace reinforce
