#include "reinforce_invocation.h"

#include "reinforce_packing_scan.h"
#include "reinforce_relocation.h"
#include "reinforce_round_plan.h"
#include "reinforce_round_runner.h"
#include "reinforce_run_stages.h"
#include "reinforce_view.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <unordered_map>

namespace reinforce {

namespace {

bool is_matrix(const AtomArrays &a, int i)
{
  return (a.mask[i] & a.group_bit) && !(a.mask[i] & (a.rebar_bit | a.frozen_bits));
}

// In the fix group, but in the rebar of another reinforce/invert fix.
bool is_left_alone(const AtomArrays &a, int i)
{
  return (a.mask[i] & a.group_bit) && !(a.mask[i] & a.rebar_bit) && (a.mask[i] & a.frozen_bits);
}

std::string format(const char *fmt, double a, double b = 0)
{
  char line[300];
  std::snprintf(line, sizeof line, fmt, a, b);
  return line;
}

// The share of targets deleted for want of a void above which the log says
// why (docs/fix_reinforce_invert.rst, "Output").
constexpr double kManyUnplaced = 0.1;
// The line that says why many targets were deleted, naming what is true of
// them: no spheres around them within `search`, a bar larger than the box,
// or no void in the accepted radius range (the usual cause in a dense
// packing of close radii, where few voids take even the smallest).
std::string unplaced_line(const Stats &s, std::int64_t no_place, double rmin, double rmax,
                          double search, double rebar_rmax, bool bar_exceeds_box)
{
  char part[300];
  std::snprintf(part, sizeof part,
                "fix reinforce/invert: unplaced: %lld of %lld targets (%.0f%%) were deleted: ",
                static_cast<long long>(no_place), static_cast<long long>(s.targets),
                100.0 * no_place / s.targets);
  std::string line = part;
  std::vector<std::string> why;
  if (bar_exceeds_box) {
    std::snprintf(part, sizeof part, "a bar sphere (radius %g) is larger than the box", rebar_rmax);
    why.emplace_back(part);
  }
  if (s.isolated > 0) {
    std::snprintf(part, sizeof part,
                  "%lld had fewer than four neighbours within search %g (the search keyword "
                  "widens it)",
                  static_cast<long long>(s.isolated), search);
    why.emplace_back(part);
  }
  const std::int64_t no_void = no_place - s.isolated;
  if (no_void > 0) {
    // Close radii: the largest at most 1.5 times the smallest accepted.
    const bool close = rmax <= 1.5 * rmin;
    std::snprintf(part, sizeof part,
                  "%lld found no void with a radius in [%g, %g] (%sthe radius keyword widens "
                  "the accepted range)",
                  static_cast<long long>(no_void), rmin, rmax,
                  close ? "in a dense packing of close radii few voids take even the smallest; "
                        : "");
    why.emplace_back(part);
  }
  for (std::size_t k = 0; k < why.size(); ++k) line += (k ? "; " : "") + why[k];
  return line + "; unplaced keep leaves them in place\n";
}

}    // namespace

namespace {

AtomRanges check_atoms(HostHooks &host, const FixOptions &options)
{
  const AtomArrays a = host.atoms();
  AtomRanges out;
  double rebar_count = 0, matrix_count = 0;
  double bad_matrix = 0, bad_rebar = 0;    // an id with radius 0 (or not finite)
  for (int i = 0; i < a.nlocal; ++i) {
    const double r = a.radius[i];
    const bool good = r > 0 && std::isfinite(r);
    if (good) out.largest = std::max(out.largest, r);
    if (a.mask[i] & a.rebar_bit) {
      rebar_count += 1;
      if (!good && bad_rebar == 0) bad_rebar = static_cast<double>(a.id(i));
    } else if (is_matrix(a, i)) {
      matrix_count += 1;
      if (!good && bad_matrix == 0) bad_matrix = static_cast<double>(a.id(i));
      out.matrix_rmin = std::min(out.matrix_rmin, r);
      out.matrix_rmax = std::max(out.matrix_rmax, r);
    }
  }
  if (host.sum(rebar_count) == 0)
    host.fail("Fix reinforce/invert rebar group '" + options.rebar_group + "' is empty");
  bad_rebar = host.max(bad_rebar);
  if (bad_rebar > 0)
    host.fail(format("Fix reinforce/invert: rebar atom %.0f has radius 0; rebar spheres need "
                     "a radius > 0",
                     bad_rebar));
  bad_matrix = host.max(bad_matrix);
  if (bad_matrix > 0)
    host.fail(format("Fix reinforce/invert: matrix atom %.0f has radius 0; matrix spheres need "
                     "a radius > 0",
                     bad_matrix));
  out.matrix_rmin = -host.max(-out.matrix_rmin);
  out.matrix_rmax = host.max(out.matrix_rmax);
  out.largest = host.max(out.largest);
  out.any_matrix = host.sum(matrix_count) > 0;
  return out;
}

Plan prepare(HostHooks &host, const FixOptions &options, const AtomRanges &ranges)
{
  Plan plan;
  plan.box = host.placement_domain();
  const Domain &box = plan.box;
  try {
    plan.settings =
        make_settings(options, ranges.matrix_rmin, ranges.matrix_rmax, norm(box.hi - box.lo));
  } catch (const OptionError &e) {
    host.fail(e.what());
  }
  const Settings &settings = plan.settings;
  if (settings.size == SizeMode::Fit && settings.rmin == settings.rmax)
    host.log(format("fix reinforce/invert: the radius range is the single radius %g: with "
                    "size fit only voids of exactly that radius fit; size keep (the default) "
                    "or the radius keyword widen it\n",
                    settings.rmin));
  const Footprint reach = footprint(settings, ranges.matrix_rmax, ranges.largest);
  // Everything a relocation reads lies within reach.read of a target's
  // centre, and a target touches a bar: the view needs no more.
  plan_rounds(host, reach.write, reach.read, "relocation", plan);
  plan.margin = reach.read + 2 * ranges.largest;
  return plan;
}

// The owned matrix spheres of the fix group that overlap a rebar sphere by
// more than tol * min radius. Each process marks only its own (owned)
// targets, so a list with rows for owned atoms is enough. The host's list
// answers when it has one that reaches matrix-rebar contact (source-built
// LAMMPS: its occasional full list); else, or when it is shorter (radii
// grew since the host set it up), the engine's grid over the view does
// (find_targets). Both decide each pair with spheres_overlap on the same
// coordinates, and both see every rebar sphere a target can overlap: a
// target touches a bar, so it is in the view, and the rebar spheres it
// overlaps lie within matrix rmax + rebar rmax of it (owned or ghost). So
// both give the same targets, in view order (tests:
// Invocation.HostListFindsTheSameTargets*, and
// src_lammps_same_as_packaged_host_list against lmp_reinforce).
std::vector<std::size_t> overlapping_bars(HostHooks &host, const Marked &m, double contact,
                                          double tol)
{
  if (!host.build_neighbour_lists(contact)) return find_targets(m.view, tol);
  std::vector<std::size_t> overlapping;
  std::vector<int> near;
  const AtomArrays &a = m.a;
  for (std::size_t k = 0; k < m.view.size(); ++k) {
    if (!m.view[k].owned || !is_matrix(a, m.local[k])) continue;
    host.neighbours(m.local[k], near);
    for (int j : near) {
      if (!(a.mask[j] & a.rebar_bit)) continue;
      if (spheres_overlap(m.view[k].x, m.view[k].r, Vec3{a.x[j][0], a.x[j][1], a.x[j][2]},
                          a.radius[j], tol)) {
        overlapping.push_back(k);
        break;
      }
    }
  }
  return overlapping;
}

Marked mark_targets(HostHooks &host, const Plan &plan, const AtomRanges &ranges, Totals &totals)
{
  const Settings &settings = plan.settings;
  Marked m;
  m.a = host.atoms();
  m.view = make_view(m.a, plan.margin, plan.domain, m.local);
  for (const Particle &p : m.view)
    if (p.role == Role::Rebar) m.rebar_rmax = std::max(m.rebar_rmax, p.r);
  const double contact = ranges.matrix_rmax + host.max(m.rebar_rmax);
  std::size_t found = 0;
  double left_alone = 0;
  for (std::size_t k : overlapping_bars(host, m, contact, settings.tol)) {
    if (is_left_alone(m.a, m.local[k])) left_alone += 1;
    if (!is_matrix(m.a, m.local[k])) continue;
    host.set_pending(m.local[k], true);
    ++found;
    m.target_rmin = std::min(m.target_rmin, m.view[k].r);
    m.target_rmax = std::max(m.target_rmax, m.view[k].r);
  }
  m.target_rmin = -host.max(-m.target_rmin);
  m.target_rmax = host.max(m.target_rmax);
  left_alone = host.sum(left_alone);
  if (left_alone > 0)
    host.log(format("fix reinforce/invert: left alone %.0f atoms that overlap the bars: they "
                    "are rebar of ",
                    left_alone) +
             m.a.frozen_by + "\n");
  m.rebar_rmax = host.max(m.rebar_rmax);
  if (host.sum(static_cast<double>(found)) == 0) return m;
  // The ghosts learn which atoms are targets (a forward communication: the
  // atoms and their order stay as they are).
  host.forward_pending();
  m.a = host.atoms();
  for (std::size_t k = 0; k < m.view.size(); ++k)
    if (m.view[k].role != Role::Rebar)
      m.view[k].role = m.a.pending[m.local[k]] ? Role::Target : Role::Matrix;
  double largest_packing = 0;
  totals.packing_overlaps = host.sum(static_cast<double>(
      count_packing_overlaps(m.view, settings.tol, settings.rmin, largest_packing)));
  totals.packing_max_overlap = host.max(largest_packing);
  if (totals.packing_overlaps > 0)
    host.log(format("fix reinforce/invert: the packing near the bars already has %.0f "
                    "overlapping pairs (largest %.2e rmin); they are left as they are\n",
                    totals.packing_overlaps, totals.packing_max_overlap));
  return m;
}

// The totals over all processes: the table's sums and maxima, each kind
// by one gather.
void reduce_totals(HostHooks &host, Totals &t)
{
  for (const Reduction kind : {Reduction::Sum, Reduction::Max}) {
    std::vector<double> mine;
    for (const TotalsField &f : totals_fields())
      if (f.reduction == kind) mine.push_back(f.get(t));
    const std::vector<double> all = reduce_all(host, mine, kind == Reduction::Max);
    std::size_t k = 0;
    for (const TotalsField &f : totals_fields())
      if (f.reduction == kind) f.set(t, all[k++]);
  }
}

}    // namespace

Totals run_invocation(HostHooks &host, const FixOptions &options)
{
  const double start = host.wall_time();
  host.refresh();
  const AtomRanges ranges = check_atoms(host, options);
  Totals totals;
  // For the log: the unit of the overlaps (the settings' rmin), the accepted
  // radius range, the search gap and the bars' largest radius.
  double unit = ranges.any_matrix ? ranges.matrix_rmin : 0, accepted_rmax = ranges.matrix_rmax;
  double search = 0, rebar_rmax = 0;
  bool bar_exceeds_box = false;
  if (!ranges.any_matrix) {
    host.warn("Fix reinforce/invert has no matrix sphere (an atom of the fix group outside the "
              "rebar group): nothing to relocate");
  } else {
    const Plan plan = prepare(host, options, ranges);
    unit = plan.settings.rmin;
    accepted_rmax = plan.settings.rmax;
    search = plan.settings.search;
    Marked marked = mark_targets(host, plan, ranges, totals);
    rebar_rmax = marked.rebar_rmax;
    for (int d = 0; d < 3; ++d)
      bar_exceeds_box = bar_exceeds_box || 2 * rebar_rmax > plan.domain.hi[d] - plan.domain.lo[d];
    run_stages(host, options, plan, ranges, marked, totals);
    host.restore_ghost_cutoff();
  }
  reduce_totals(host, totals);
  fold_regrowth(totals);
  const Stats &s = totals.stats;
  totals.deleted = options.keep_unplaced ? 0 : static_cast<double>(s.unplaced);
  totals.kept = options.keep_unplaced ? static_cast<double>(s.unplaced) : 0;
  totals.seconds = host.max(host.wall_time() - start);
  if (totals.regrowth.seeds + totals.regrowth.shrunk_seeds > 0)
    host.log(regrowth_line(totals.regrowth, totals.regrowth_seconds));
  host.log(summary_line(s, options.keep_unplaced, totals.seconds, totals.rounds, unit));
  // Many targets that found no place (and no regrowth ran): say why and
  // what changes it.
  const std::int64_t no_place = s.unplaced - s.displaced;
  if (!options.keep_unplaced && totals.regrowth.seeds == 0 && s.targets > 0 &&
      no_place >= kManyUnplaced * s.targets)
    host.log(unplaced_line(s, no_place, unit, accepted_rmax, search, rebar_rmax, bar_exceeds_box));
  return totals;
}

}    // namespace reinforce
