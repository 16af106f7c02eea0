// The phases of one invocation (reinforce_invocation.cpp) and the stages they run
// (reinforce_run_stages.cpp): what they pass each other. Internal to the engine.
#pragma once

#include "reinforce_invocation.h"
#include "reinforce_schedule.h"

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

// The settings, the schedule, the ghost reach it needs (raised on the
// host) and this process's view bounds and partners.
struct Plan {
  Settings settings;
  Domain box, domain;
  BlockLattice lattice;
  std::vector<int> partners;
  double margin = 0;    // the view: atoms within this of a rebar sphere
};

// The view with its targets marked (owned ones by this process, ghost ones
// from their owners), and what the log needs about them.
struct Marked {
  AtomArrays a;
  std::vector<int> local;
  std::vector<Particle> view;
  double target_rmin = INFINITY, target_rmax = 0, rebar_rmax = 0;
};

// The engine's view of the atoms within `margin` of a rebar sphere and
// inside the domain's view bounds; `local` gets their host indices.
std::vector<Particle> make_view(const AtomArrays &a, double margin, const Domain &domain,
                                std::vector<int> &local);

// The lattice for a stage whose unit of work writes within `write` and
// reads within `read` of its particle, the ghost reach that needs (raised
// on the host), this process's view bounds and its partners.
void plan_rounds(HostHooks &host, double write, double read, const char *stage, Plan &plan);

// The stages on the schedule (relocation, then the regrowth where targets
// are left without a place), the deletions, and the schedule lines.
void run_stages(HostHooks &host, const FixOptions &options, const Plan &plan,
                const AtomRanges &ranges, Marked &m, Totals &totals);

// The regrowth's outcome in the relocation's totals, and its log line.
void fold_regrowth(Totals &t);
std::string regrowth_line(const RegrowthStats &g, double seconds);

}    // namespace reinforce
