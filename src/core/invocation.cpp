#include "invocation.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace reinforce {

namespace {

// The engine's view of the atoms that can matter: those within `margin` of
// a rebar sphere. Every atom is an obstacle; pending ones are vacant.
std::vector<Particle> make_view(const AtomArrays &a, double margin, std::vector<int> &local)
{
  std::vector<unsigned char> rebar(a.nall);
  for (int i = 0; i < a.nall; ++i) rebar[i] = (a.mask[i] & a.rebar_bit) != 0;
  local = spheres_near_rebar(a.nall, a.x, a.radius, rebar.data(), margin);
  std::vector<Particle> view;
  view.reserve(local.size());
  for (int i : local) {
    Particle p;
    p.x = {a.x[i][0], a.x[i][1], a.x[i][2]};
    p.r = a.radius[i];
    p.id = a.tag[i];
    p.role = rebar[i] ? Role::Rebar : (a.pending[i] ? Role::Target : Role::Matrix);
    p.owned = i < a.nlocal;
    view.push_back(p);
  }
  return view;
}

bool is_matrix(const AtomArrays &a, int i)
{
  return (a.mask[i] & a.group_bit) && !(a.mask[i] & a.rebar_bit);
}

}    // namespace

std::array<double, kOutputSize> output_vector(const Totals &t)
{
  const Stats &s = t.stats;
  return {static_cast<double>(s.targets),
          static_cast<double>(s.relocated),
          t.deleted,
          t.kept,
          s.volume_before,
          s.volume_after,
          s.max_overlap,
          static_cast<double>(s.solves),
          t.seconds,
          t.packing_overlaps};
}

Totals run_invocation(HostHooks &host, const FixOptions &options)
{
  const double start = host.wall_time();
  host.refresh();

  // Radius range of the matrix and the largest sphere, over all processes.
  AtomArrays a = host.atoms();
  double matrix_rmin = INFINITY, matrix_rmax = 0, largest = 0, rebar_count = 0, matrix_count = 0;
  for (int i = 0; i < a.nlocal; ++i) {
    largest = std::max(largest, a.radius[i]);
    if (a.mask[i] & a.rebar_bit) {
      rebar_count += 1;
    } else if (is_matrix(a, i)) {
      matrix_count += 1;
      matrix_rmin = std::min(matrix_rmin, a.radius[i]);
      matrix_rmax = std::max(matrix_rmax, a.radius[i]);
    }
  }
  if (host.sum(rebar_count) == 0)
    host.fail("Fix reinforce/invert rebar group '" + options.rebar_group + "' is empty");
  matrix_rmin = -host.max(-matrix_rmin);
  matrix_rmax = host.max(matrix_rmax);
  largest = host.max(largest);

  Totals totals;
  if (host.sum(matrix_count) > 0) {    // else: no matrix sphere, nothing to relocate
    Settings settings;
    try {
      settings = make_settings(options, matrix_rmin, matrix_rmax);
    } catch (const OptionError &e) {
      host.fail(e.what());
    }
    const double reach = required_reach(settings, matrix_rmax, largest);
    // Two same-round processes are one subdomain apart; each may place a
    // sphere up to target_r + search + rmax beyond its own subdomain.
    host.check_subdomain_width(2 * (matrix_rmax + settings.search + settings.rmax));
    host.ensure_ghost_cutoff(reach);

    a = host.atoms();
    std::vector<int> local;
    std::vector<Particle> view = make_view(a, 2 * reach, local);
    for (std::size_t k : find_targets(view, settings.tol))
      if (is_matrix(a, local[k])) host.set_pending(local[k], true);
    host.forward_pending();
    double largest_packing = 0;
    totals.packing_overlaps = host.sum(static_cast<double>(
        count_packing_overlaps(view, settings.tol, settings.rmin, largest_packing)));
    totals.packing_max_overlap = host.max(largest_packing);
    if (totals.packing_overlaps > 0) {
      char line[200];
      std::snprintf(line, sizeof line,
                    "fix reinforce/invert: the packing near the bars already has %.0f overlapping "
                    "pairs (largest %.2e rmin); they are left as they are\n",
                    totals.packing_overlaps, totals.packing_max_overlap);
      host.log(line);
    }

    const Rounds rounds = host.rounds();
    const Domain domain = host.placement_domain();
    for (int round = 0; round < rounds.count; ++round) {
      if (round == rounds.mine) {
        a = host.atoms();
        view = make_view(a, 2 * reach, local);
        const std::vector<Placement> placements =
            relocate_targets(view, settings, domain, options.keep_unplaced, totals.stats);
        std::vector<int> doomed;
        for (const Placement &p : placements) {
          const int i = local[p.index];
          if (p.placed) {
            host.move(i, p.x, p.r);
          } else if (options.keep_unplaced) {
            host.set_pending(i, false);
          } else {
            doomed.push_back(i);
          }
        }
        host.remove(doomed);
      }
      // The next round's processes must see this round's spheres.
      if (rounds.count > 1) host.refresh();
    }
    host.restore_ghost_cutoff();
  }

  Stats &s = totals.stats;
  s.targets = static_cast<std::int64_t>(host.sum(static_cast<double>(s.targets)));
  s.relocated = static_cast<std::int64_t>(host.sum(static_cast<double>(s.relocated)));
  s.unplaced = static_cast<std::int64_t>(host.sum(static_cast<double>(s.unplaced)));
  s.solves = static_cast<std::int64_t>(host.sum(static_cast<double>(s.solves)));
  s.volume_before = host.sum(s.volume_before);
  s.volume_after = host.sum(s.volume_after);
  s.max_overlap = host.max(s.max_overlap);
  totals.deleted = options.keep_unplaced ? 0 : static_cast<double>(s.unplaced);
  totals.kept = options.keep_unplaced ? static_cast<double>(s.unplaced) : 0;
  totals.seconds = host.max(host.wall_time() - start);
  host.log(summary_line(s, options.keep_unplaced, totals.seconds));
  return totals;
}

}    // namespace reinforce
