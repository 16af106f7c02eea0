// The engine's view of a host's atoms: the spheres near the bars that a
// stage can read, as Particles (docs/design.md, "The relocation engine").
#pragma once

#include "reinforce_domain.h"
#include "reinforce_host_hooks.h"
#include "reinforce_particle.h"

#include <vector>

namespace reinforce {

// The atoms within `margin` of a rebar sphere and inside the domain's view
// bounds; `local` gets their host indices. Every atom is an obstacle;
// pending ones are vacant; only matrix atoms of the fix group are pushed.
std::vector<Particle> make_view(const AtomArrays &a, double margin, const Domain &domain,
                                std::vector<int> &local);

}    // namespace reinforce
