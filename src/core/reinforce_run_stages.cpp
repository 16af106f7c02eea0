#include "reinforce_run_stages.h"

#include "reinforce_relocation.h"
#include "reinforce_relocation_stage.h"
#include "reinforce_round_records.h"
#include "reinforce_regrowth_policy.h"
#include "reinforce_round_runner.h"
#include "reinforce_view.h"

#include <algorithm>
#include <cstdio>

namespace reinforce {

namespace {

// The schedule line of a stage: its rounds, its units of work and how
// evenly they fell on the processes (1 = even).
void log_schedule(HostHooks &host, const char *stage, const char *units, const RoundsDone &done,
                  double work)
{
  char line[300];
  std::snprintf(line, sizeof line,
                "fix reinforce/invert: %s: %d rounds, %.0f %s in %.0f blocks, busiest "
                "process %.0f %s over the rounds, balance %.2f over %.0f processes\n",
                stage, done.rounds, work, units, done.blocks, done.busiest, units,
                work / (done.busiest * done.processes), done.processes);
  host.log(line);
}

// Every process's targets placed shrunk across thin bars, in id order
// (carried as records: their IDs exact).
std::vector<ShrunkTarget> gather_shrunk(HostHooks &host, const std::vector<ShrunkTarget> &mine)
{
  std::vector<RoundRecord> records;
  for (const ShrunkTarget &t : mine) records.push_back({t.id, RecordKind::Placed, t.x0, t.r0});
  std::vector<double> flat;
  encode_records(records, flat);
  if (!decode_records(host.gather_all(flat), records))
    host.fail("Fix reinforce/invert: internal error: malformed list of shrunk targets");
  std::vector<ShrunkTarget> out;
  for (const RoundRecord &r : records) out.push_back({r.id, r.v, r.r});
  std::sort(out.begin(), out.end(),
            [](const ShrunkTarget &a, const ShrunkTarget &b) { return a.id < b.id; });
  return out;
}

// The regrowth of the targets the relocation left pending and of those it
// placed shrunk (`shrunk`, every process's), after the host's refresh with
// the ghosts reaching what it reads.
void regrow_pending(HostHooks &host, const Plan &plan, const AtomRanges &ranges,
                    std::vector<ShrunkTarget> shrunk, Totals &totals)
{
  const double start = host.wall_time();
  RegrowthInput in;
  in.settings = plan.settings;
  in.width = plan.settings.regrow;
  in.matrix_rmin = ranges.matrix_rmin;
  in.matrix_rmax = ranges.matrix_rmax;
  in.largest = ranges.largest;
  in.shrunk = std::move(shrunk);
  raise_ghost_cutoff(host,
                     regrowth_ghost_reach(in.matrix_rmax, in.largest, plan.settings.search),
                     "regrowth");
  host.refresh();
  in.domain = host.placement_domain();
  regrow(host, in, totals.regrowth);
  totals.regrowth_seconds = host.max(host.wall_time() - start);
}

}    // namespace

// The stages on the schedule (relocation, then the regrowth where targets
// are left without a place), the deletions, and the schedule lines.
void run_stages(HostHooks &host, const FixOptions &options, const Plan &plan,
                const AtomRanges &ranges, Marked &m, Totals &totals)
{
  const Settings &settings = plan.settings;
  double view_largest = settings.rmax;
  for (const Particle &p : m.view) view_largest = std::max(view_largest, p.r);
  const Unplaced unplaced = options.keep_unplaced
                                ? Unplaced::Keep
                                : (settings.regrow > 0 ? Unplaced::Defer : Unplaced::Delete);
  RelocationStage relocation(settings, plan.domain, unplaced, m.target_rmin, m.target_rmax,
                             footprint(settings, m.target_rmax, view_largest).read, totals.stats);
  std::vector<int> doomed;
  const RoundsDone done =
      run_rounds(host, relocation, {plan.lattice, plan.box, plan.domain, plan.partners},
                 std::move(m.view), m.local, m.a, doomed);
  totals.rounds = done.rounds;
  host.remove(doomed);
  const double targets = host.sum(static_cast<double>(totals.stats.targets));
  if (totals.rounds == 0) return;
  log_schedule(host, "schedule", "targets", done, targets);
  if (unplaced != Unplaced::Defer) return;
  const Stats &s = totals.stats;
  std::vector<ShrunkTarget> shrunk;
  if (settings.size == SizeMode::Keep) shrunk = gather_shrunk(host, relocation.placed_shrunk());
  if (host.sum(static_cast<double>(s.unplaced - s.displaced)) > 0 || !shrunk.empty())
    regrow_pending(host, plan, ranges, shrunk, totals);
}

// The regrowth's outcome in the relocation's totals, so that they say
// what became of every target: a regrown target is relocated, and its
// volume is back.
void fold_regrowth(Totals &t)
{
  const RegrowthStats &g = t.regrowth;
  Stats &s = t.stats;
  s.relocated += g.regrown;
  s.shrunk -= g.shrunk_regrown;
  s.unplaced -= g.regrown;
  s.displaced += g.displaced;
  s.volume_after += g.volume_regrown + g.volume_unshrunk;
  // What the shrunk targets get back was never removed (f_ID[12] counts
  // the targets deleted or kept).
  s.volume_removed -= g.volume_regrown;
  t.relocation_max_overlap = s.max_overlap;
  s.max_overlap = std::max(s.max_overlap, g.max_overlap);
}

std::string regrowth_line(const RegrowthStats &g, double seconds)
{
  char line[500];
  std::snprintf(line, sizeof line,
                "fix reinforce/invert: regrowth: %lld targets without a void, %lld regrown at "
                "their own radius, %lld deleted (%lld inside the bars); %lld placed shrunk taken "
                "up, %lld regrown at their own radius; %lld matrix spheres moved (largest %.2f "
                "rmin), %lld steps, max overlap %.2e rmin (%lld spheres above %.0e of the "
                "smaller radius), %.3f s",
                static_cast<long long>(g.seeds), static_cast<long long>(g.regrown),
                static_cast<long long>(g.deleted), static_cast<long long>(g.displaced),
                static_cast<long long>(g.shrunk_seeds), static_cast<long long>(g.shrunk_regrown),
                static_cast<long long>(g.moved), g.max_move, static_cast<long long>(g.sweeps),
                g.max_overlap, static_cast<long long>(g.inexact), regrowth_policy::kRegrowthExact,
                seconds);
  std::string out = line;
  if (g.jammed) {
    std::snprintf(line, sizeof line,
                  "; the zone jammed at %.3f of the radii and went back to the relocation's "
                  "scene",
                  g.jam_scale);
    out += line;
  }
  return out + "\n";
}

}    // namespace reinforce
