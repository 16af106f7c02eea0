#include "reinforce_round_plan.h"

#include "reinforce_round_runner.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace reinforce {

void raise_ghost_cutoff(HostHooks &host, double cutoff, const char *stage)
{
  if (!std::isfinite(cutoff))
    host.fail(std::string("Fix reinforce/invert: the reach of the ") + stage + " is not finite");
  const GhostCutoff ghosts = host.ensure_ghost_cutoff(cutoff);
  if (ghosts.raised) {
    char line[300];
    std::snprintf(line, sizeof line,
                  "fix reinforce/invert: ghost cutoff raised from %g to %g for the %s\n",
                  ghosts.before, ghosts.after, stage);
    host.log(line);
  }
}

void plan_rounds(HostHooks &host, double write, double read, const char *stage, Plan &plan)
{
  const Domain &box = plan.box;
  plan.lattice = make_block_lattice(box.lo, box.hi, box.periodic, write + read);
  // The owner of a block's centre sees the whole block plus the read
  // reach: how far a block reaches past a subdomain depends on where the
  // subdomain's faces fall on the lattice, so the largest over processes.
  const double beyond = host.max(plan.lattice.reach_beyond(box.sub_lo, box.sub_hi));
  const double cutoff = beyond + read;
  raise_ghost_cutoff(host, cutoff, stage);
  // The view needs no more than the cutoff past the subdomain, whatever
  // the host's ghosts hold: the results of the rounds reach this process
  // only from the processes that can change something within that
  // (exchange_partners).
  plan.domain = host.placement_domain();
  for (int d = 0; d < 3; ++d) {
    plan.domain.view_lo[d] = std::max(plan.domain.view_lo[d], plan.domain.sub_lo[d] - cutoff);
    plan.domain.view_hi[d] = std::min(plan.domain.view_hi[d], plan.domain.sub_hi[d] + cutoff);
  }
  plan.partners = exchange_partners(host, plan.domain, beyond, write, cutoff);
}

}    // namespace reinforce
