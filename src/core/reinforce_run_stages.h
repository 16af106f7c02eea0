// The stages of one invocation on the block schedule: the relocation, then
// the regrowth where targets are left without a place (docs/design.md,
// "Stages").
#pragma once

#include "reinforce_fix_options.h"
#include "reinforce_host_hooks.h"
#include "reinforce_particle.h"
#include "reinforce_regrowth.h"
#include "reinforce_round_plan.h"
#include "reinforce_totals.h"

#include <cmath>
#include <string>
#include <vector>

namespace reinforce {

// The matrix and the rebar as this invocation finds them, over all
// processes; stops at an empty rebar group or a sphere of radius 0.
struct AtomRanges {
  double matrix_rmin = INFINITY, matrix_rmax = 0, largest = 0;
  bool any_matrix = false;
};

// The view with its targets marked (owned ones by this process, ghost ones
// from their owners), and what the log needs about them.
struct Marked {
  AtomArrays a;
  std::vector<int> local;
  std::vector<Particle> view;
  double target_rmin = INFINITY, target_rmax = 0, rebar_rmax = 0;
};

// The stages on the schedule (relocation, then the regrowth where targets
// are left without a place), the deletions, and the schedule lines.
void run_stages(HostHooks &host, const FixOptions &options, const Plan &plan,
                const AtomRanges &ranges, Marked &m, Totals &totals);

// The regrowth's outcome in the relocation's totals, and its log line.
void fold_regrowth(Totals &t);
std::string regrowth_line(const RegrowthStats &g, double seconds);

}    // namespace reinforce
