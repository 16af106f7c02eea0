#include "reinforce_regrowth.h"

#include "reinforce_ball_sample.h"
#include "reinforce_growth_schedule.h"
#include "reinforce_regrowth_count.h"
#include "reinforce_regrowth_policy.h"
#include "reinforce_regrowth_zone.h"
#include "reinforce_soft_relaxation.h"

#include <algorithm>
#include <cmath>
#include <tuple>
#include <unordered_map>

namespace reinforce {

using namespace regrowth_policy;

namespace {

// How far a sphere may move, and how far a moving sphere reads: its
// neighbours within both radii and the lists' skin, each within its cap.
double cap_of(double matrix_rmax)
{
  return kCapShare * matrix_rmax;
}
double touch_reach(double matrix_rmax, double largest)
{
  return 2 * cap_of(matrix_rmax) + matrix_rmax + largest + (kSkin + kPad) * matrix_rmax;
}

// Where an owned kept seed starts: where it was before the relocation
// (its old centre; a target placed shrunk leaves its shrunk place), pushed
// out of the bar spheres it overlaps at kGrowStart of its radius (a few
// passes, for the beads of a chain); at its atom's place if that leaves
// its cap or the walls refuse it (the growth pushes it out then).
void start_out_of_bars(Zone &zone, const std::vector<Seed> &seeds, const Domain &domain,
                       double start, double tol)
{
  std::unordered_map<std::int64_t, const Seed *> seed_of;
  for (const Seed &s : seeds) seed_of[s.id] = &s;
  // The bars in (id, place) order: the passes push along them in turn.
  std::vector<int> bars;
  for (std::size_t k = 0; k < zone.bodies.size(); ++k)
    if (zone.bodies[k].rebar) bars.push_back(static_cast<int>(k));
  std::sort(bars.begin(), bars.end(), [&](int p, int q) {
    const ZoneBody &a = zone.bodies[p], &b = zone.bodies[q];
    return std::tie(a.id, a.x0.x, a.x0.y, a.x0.z) < std::tie(b.id, b.x0.x, b.x0.y, b.x0.z);
  });
  for (int m : zone.moving) {
    ZoneBody &seed = zone.bodies[static_cast<std::size_t>(m)];
    if (!seed.growing) continue;
    const double r = start * seed.R;
    // Its old centre, the copy nearest its atom.
    Vec3 x = seed_of.at(seed.id)->x;
    for (int d = 0; d < 3; ++d)
      if (domain.periodic[d]) {
        const double period = domain.hi[d] - domain.lo[d];
        x[d] -= period * std::round((x[d] - seed.x0[d]) / period);
      }
    for (int pass = 0; pass < 3; ++pass)
      for (int k : bars) {
        const ZoneBody &o = zone.bodies[static_cast<std::size_t>(k)];
        const double d = norm(x - o.x0);
        if (!(d < o.R + r)) continue;
        const Vec3 n =
            d > 1e-12 * o.R ? (1 / d) * (x - o.x0) : Vec3{seed.id < o.id ? -1.0 : 1.0, 0, 0};
        x = o.x0 + (o.R + r) * n;
      }
    if (norm(x - seed.x0) <= seed.cap && admissible(seed.x0, x, seed.R, domain, tol)) zone.x[m] = x;
  }
}

// The outcome on the host's owned atoms: the seeds put back or deleted, the
// moved matrix, and the counts.
void apply(HostHooks &host, const Zone &zone, const std::vector<Seed> &seeds, double rmin,
           RegrowthStats &stats)
{
  std::unordered_map<std::int64_t, const Seed *> seed_of;
  for (const Seed &s : seeds) seed_of[s.id] = &s;
  std::vector<int> doomed;
  for (std::size_t k = 0; k < zone.bodies.size(); ++k) {
    const ZoneBody &b = zone.bodies[k];
    if (!b.owned) continue;
    const Vec3 x = zone.x[k];
    const auto found = seed_of.find(b.id);
    const bool moved = norm2(x - b.x0) > 0;
    if (found == seed_of.end()) {
      if (!b.movable || !moved) continue;
      stats.moved++;
      stats.max_move = std::max(stats.max_move, norm(x - b.x0) / rmin);
      host.move(b.local, x, b.R);
      continue;
    }
    const Seed &seed = *found->second;
    const bool back = b.present && b.growing;
    if (seed.r > 0) {
      stats.shrunk_seeds++;
      if (back) {
        stats.shrunk_regrown++;
        stats.volume_unshrunk += ball_volume(seed.R) - ball_volume(seed.r);
      }
      if (back || moved) host.move(b.local, x, back ? seed.R : seed.r);
      continue;
    }
    stats.seeds++;
    if (back) {
      stats.regrown++;
      stats.volume_regrown += ball_volume(seed.R);
      host.move(b.local, x, seed.R);
    } else {
      stats.deleted++;
      if (seed.depth < 0) stats.displaced++;
      doomed.push_back(b.local);
    }
  }
  host.remove(doomed);
}

}    // namespace

double regrowth_ghost_reach(double matrix_rmax, double largest, double search)
{
  const double pull = kPullRange * matrix_rmax + largest;
  const double shrunk = 2 * matrix_rmax + search + largest;
  return std::max({touch_reach(matrix_rmax, largest), pull, shrunk}) * (1 + 1e-9);
}

void regrow(HostHooks &host, const RegrowthInput &in, RegrowthStats &stats)
{
  const AtomArrays a = host.atoms();
  std::vector<Seed> seeds = gather_seeds(host, a, in.shrunk, in.domain);
  if (seeds.empty()) return;
  count_kept(seeds, kBalanceShare);
  ZoneShape shape;
  shape.width = in.width;
  shape.cap = cap_of(in.matrix_rmax);
  shape.reach = in.width + touch_reach(in.matrix_rmax, in.largest);
  shape.pull_range = kPullRange * in.matrix_rmax;
  Zone zone(host, a, seeds, shape, in.domain);
  start_out_of_bars(zone, seeds, in.domain, kGrowStart, in.settings.tol);
  zone.forward_positions();
  SoftRelaxation relax(host, zone, in.domain, in.settings.tol, in.matrix_rmin, in.matrix_rmax);
  relax.set_scale(kGrowStart);
  Growth growth(host, zone, relax, seeds);
  const GrowthOutcome outcome = growth.run(kGrowStart);
  stats.sweeps = relax.steps();
  if (outcome.clear) {
    // At their own radii, against everything present, beyond what each
    // pair overlapped at the start.
    std::int64_t above = 0;
    relax.set_scale(1);
    stats.max_overlap = relax.worst_at_full_size(kRegrowthExact, above);
    stats.inexact = above;
  } else {
    // Back to the relocation's scene, its targets without a void deleted.
    stats.jammed = 1;
    stats.jam_scale = outcome.scale;
    growth.undo(seeds);
  }
  apply(host, zone, seeds, in.matrix_rmin, stats);
}

}    // namespace reinforce
