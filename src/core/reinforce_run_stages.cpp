#include "reinforce_run_stages.h"

#include "reinforce_regrowth_stage.h"
#include "reinforce_relocation.h"
#include "reinforce_relocation_stage.h"
#include "reinforce_round_records.h"
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

// The regrowth of the targets the relocation left pending, and of those it
// placed shrunk across thin bars (`shrunk`, every process's: each is a
// vacant target where it was, with its images, beside its shrunk sphere):
// a view made again after the host's refresh (the relocation moved atoms
// across subdomains), its own lattice and ghost reach.
void regrow_pending(HostHooks &host, const Plan &relocation_plan, const AtomRanges &ranges,
                    const std::vector<ShrunkTarget> &shrunk, Totals &totals)
{
  const double start = host.wall_time();
  Plan plan = relocation_plan;
  const RegrowthReach reach =
      regrowth_reach(plan.settings.regrow, ranges.matrix_rmax, ranges.largest);
  plan_rounds(host, reach.write, reach.read, "regrowth", plan);
  host.refresh();
  const AtomArrays a = host.atoms();
  std::vector<int> local;
  std::vector<Particle> view = make_view(a, reach.read + 2 * ranges.largest, plan.domain, local);
  for (const ShrunkTarget &t : shrunk) {
    Particle p;
    p.id = t.id;
    p.r = t.r0;
    p.role = Role::Target;
    for (const Vec3 &image :
         images_in_view(wrapped_into_box(t.x0, plan.domain), plan.domain, true)) {
      p.x = image;
      view.push_back(p);
      local.push_back(-1);    // no atom of the host's: never owned
    }
  }
  RegrowthStage regrowth(plan.settings, plan.domain, plan.lattice, plan.settings.regrow,
                         ranges.matrix_rmax, ranges.largest, totals.regrowth);
  std::vector<int> doomed;
  const RoundsDone done =
      run_rounds(host, regrowth, {plan.lattice, plan.box, plan.domain, plan.partners},
                 std::move(view), local, a, doomed);
  host.remove(doomed);
  const double seeds =
      host.sum(static_cast<double>(totals.regrowth.seeds + totals.regrowth.shrunk_seeds));
  if (done.rounds > 0) log_schedule(host, "regrowth schedule", "targets", done, seeds);
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
  if (settings.size == SizeMode::Keep) shrunk = gather_shrunk(host, relocation.shrunk_by_thin());
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
  s.volume_after += g.volume_regrown;
  s.volume_removed -= g.volume_regrown;
  t.relocation_max_overlap = s.max_overlap;
  s.max_overlap = std::max(s.max_overlap, g.max_overlap);
}

std::string regrowth_line(const RegrowthStats &g, double seconds)
{
  char line[400];
  std::snprintf(line, sizeof line,
                "fix reinforce/invert: regrowth: %lld targets without a void, %lld regrown at "
                "their own radius, %lld deleted (%lld inside the bars); %lld placed shrunk taken "
                "up, %lld regrown at their own radius; %lld matrix spheres moved (largest %.2f "
                "rmin), %lld sweeps, max overlap %.2e rmin (%lld spheres above %.0e of the "
                "smaller radius), %.3f s\n",
                static_cast<long long>(g.seeds), static_cast<long long>(g.regrown),
                static_cast<long long>(g.deleted), static_cast<long long>(g.displaced),
                static_cast<long long>(g.shrunk_seeds), static_cast<long long>(g.shrunk_regrown),
                static_cast<long long>(g.moved), g.max_move, static_cast<long long>(g.sweeps),
                g.max_overlap, static_cast<long long>(g.inexact), regrowth_policy::kRegrowthExact,
                seconds);
  return line;
}

}    // namespace reinforce
