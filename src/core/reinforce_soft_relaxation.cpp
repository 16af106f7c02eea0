#include "reinforce_soft_relaxation.h"

#include "reinforce_cell_grid.h"
#include "reinforce_exact_sum.h"
#include "reinforce_regrowth_policy.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <tuple>

namespace reinforce {

using namespace regrowth_policy;

namespace {

// The direction from o to b at distance dist; for coincident centres one
// fixed by the ids (the same on every process).
Vec3 apart(const ZoneBody &b, const ZoneBody &o, double dist)
{
  if (dist > 1e-12 * (b.R + o.R)) return (1 / dist) * (b.x - o.x);
  return Vec3{b.id < o.id ? -1.0 : 1.0, 0, 0};
}

}    // namespace

SoftRelaxation::SoftRelaxation(HostHooks &host, Zone &zone, const Domain &domain, double tol,
                               double rmin, double rmax)
    : host_(host), zone_(zone), domain_(domain), tol_(tol), rmin_(rmin), skin_(kSkin * rmax),
      step_max_(kFireStep * rmax)
{
  const std::vector<ZoneBody> &bodies = zone_.bodies;
  std::vector<int> order(bodies.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int p, int q) {
    const ZoneBody &a = bodies[p], &b = bodies[q];
    return std::tie(a.id, a.x0.x, a.x0.y, a.x0.z) < std::tie(b.id, b.x0.x, b.x0.y, b.x0.z);
  });
  rank_.resize(bodies.size());
  for (std::size_t k = 0; k < order.size(); ++k) rank_[order[k]] = static_cast<int>(k);
  const std::size_t n = zone_.moving.size();
  slot_.assign(bodies.size(), -1);
  for (std::size_t m = 0; m < n; ++m) slot_[static_cast<std::size_t>(zone_.moving[m])] = static_cast<int>(m);
  near_.assign(n, {});
  built_.assign(n, Vec3{});
  v_.assign(n, Vec3{});
  f_.assign(n, Vec3{});
}

// Each moving body's neighbours: the present bodies within both radii,
// the skin and a pad of it, in (id, place) order, with what the pair
// overlapped at the start when both are spheres of the packing.
void SoftRelaxation::build_lists()
{
  const std::vector<ZoneBody> &bodies = zone_.bodies;
  double largest = 0, movable = 0;
  for (const ZoneBody &b : bodies) {
    largest = std::max(largest, b.R);
    if (b.movable) movable = std::max(movable, b.R);
  }
  const double margin = skin_ + kPad * movable;
  CellGrid grid(2 * movable + margin);
  for (std::size_t k = 0; k < bodies.size(); ++k)
    if (bodies[k].present) grid.insert(bodies[k].x, static_cast<int>(k));
  for (std::size_t m = 0; m < zone_.moving.size(); ++m) {
    const int i = zone_.moving[m];
    const ZoneBody &b = bodies[static_cast<std::size_t>(i)];
    std::vector<Neighbour> &list = near_[m];
    list.clear();
    built_[m] = b.x;
    if (!b.present) continue;
    grid.for_each_near(b.x, b.R + largest + margin, [&](int j) {
      const ZoneBody &o = bodies[static_cast<std::size_t>(j)];
      if (j == i || !(norm(b.x - o.x) < b.R + o.R + margin)) return;
      const double allowed =
          b.matrix && o.matrix ? std::max(0.0, pair_overlap(b.x0, b.R, o.x0, o.R, 0)) : 0;
      list.push_back({j, allowed});
    });
    std::sort(list.begin(), list.end(),
              [&](const Neighbour &p, const Neighbour &q) { return rank_[p.j] < rank_[q.j]; });
  }
  moved_ = 0;
  stale_ = false;
}

// The forces on the moving bodies (their overlaps, harmonic, unit
// stiffness; the pull towards their bar). Returns the largest overlap
// here, over the smaller radius.
double SoftRelaxation::forces()
{
  const std::vector<ZoneBody> &bodies = zone_.bodies;
  double worst = 0;
  for (std::size_t m = 0; m < zone_.moving.size(); ++m) {
    const ZoneBody &b = bodies[static_cast<std::size_t>(zone_.moving[m])];
    Vec3 F;
    if (b.present) {
      const double ri = radius(b);
      for (const Neighbour &n : near_[m]) {
        const ZoneBody &o = bodies[static_cast<std::size_t>(n.j)];
        if (!o.present) continue;
        const double rj = radius(o);
        double contact = ri + rj - n.allowed;
        if (pad_ > 0 && o.movable) contact += pad_ * std::min(ri, rj);
        const double d2 = norm2(b.x - o.x);
        if (d2 >= contact * contact) continue;
        const double dist = std::sqrt(d2);
        const double delta = contact - dist;
        worst = std::max(worst, delta / std::min(ri, rj));
        F = F + delta * apart(b, o, dist);
      }
      if (pull_ > 0 && b.bar >= 0) {
        const Vec3 to_bar = bodies[static_cast<std::size_t>(b.bar)].x - b.x;
        const double d = norm(to_bar);
        if (d > 0) F = F + (pull_ * b.R * b.w / d) * to_bar;
      }
    }
    f_[m] = F;
  }
  return worst;
}

// FIRE's sums and the largest overlap and move, over every process; the
// sums exact, so the same whatever the partition.
double SoftRelaxation::reduce(double worst, double &power, double &vnorm, double &fnorm)
{
  const double unit = rmin_ * rmin_;
  ExactSum p(unit), vv(unit), ff(unit);
  for (std::size_t m = 0; m < f_.size(); ++m) {
    p.add(dot(f_[m], v_[m]));
    vv.add(norm2(v_[m]));
    ff.add(norm2(f_[m]));
  }
  std::vector<double> sums;
  for (const ExactSum *s : {&p, &vv, &ff}) {
    const auto limbs = s->limbs();
    sums.insert(sums.end(), limbs.begin(), limbs.end());
  }
  host_.sum_each(sums);
  power = ExactSum::from_limbs(&sums[0], unit);
  vnorm = std::sqrt(std::max(0.0, ExactSum::from_limbs(&sums[ExactSum::kLimbs], unit)));
  fnorm = std::sqrt(std::max(0.0, ExactSum::from_limbs(&sums[2 * ExactSum::kLimbs], unit)));
  double moved = 0;
  for (std::size_t m = 0; m < zone_.moving.size(); ++m)
    moved = std::max(moved, norm(zone_.bodies[zone_.moving[m]].x - built_[m]));
  std::vector<double> maxima{worst, moved};
  host_.max_each(maxima);
  moved_ = maxima[1];
  return maxima[0];
}

// One step of each moving body: within its cap (sliding along it), along
// the box faces, and not where the walls or region refuse it.
void SoftRelaxation::move(double dt)
{
  for (std::size_t m = 0; m < zone_.moving.size(); ++m) {
    ZoneBody &b = zone_.bodies[static_cast<std::size_t>(zone_.moving[m])];
    if (!b.present) continue;
    Vec3 &v = v_[m];
    v = v + dt * f_[m];
    Vec3 d = dt * v;
    const double dn = norm(d);
    if (dn > kFireStep * b.R) d = (kFireStep * b.R / dn) * d;
    Vec3 to = b.x + d;
    const double off = norm(to - b.x0);
    if (off > b.cap) {
      const Vec3 n = (1 / off) * (to - b.x0);
      to = b.x0 + b.cap * n;
      const double out = dot(v, n);
      if (out > 0) v = v - out * n;
    }
    for (int a = 0; a < 3; ++a) {
      if (domain_.periodic[a]) continue;
      const double lo = domain_.lo[a] + b.R, hi = domain_.hi[a] - b.R;
      if (to[a] < lo && b.x[a] >= lo) {
        to[a] = lo;
        v[a] = 0;
      } else if (to[a] > hi && b.x[a] <= hi) {
        to[a] = hi;
        v[a] = 0;
      }
    }
    if (!admissible(b.x, to, b.R, domain_, tol_)) {
      v = Vec3{};
      continue;
    }
    b.x = to;
  }
}

double SoftRelaxation::run(int steps, double done)
{
  double dt = kFireDt, alpha = kFireAlpha;
  int positive = 0;
  std::fill(v_.begin(), v_.end(), Vec3{});
  if (stale_) build_lists();
  double power = 0, vn = 0, fn = 0;
  double worst = reduce(forces(), power, vn, fn);
  for (int it = 0; it < steps && worst > done; ++it) {
    steps_++;
    if (power > 0) {
      if (fn > 0)
        for (std::size_t m = 0; m < v_.size(); ++m)
          v_[m] = (1 - alpha) * v_[m] + (alpha * vn / fn) * f_[m];
      if (++positive > kFireDelay) {
        dt = std::min(dt * kFireGrow, kFireDtMax);
        alpha *= kFireAlphaDecay;
      }
    } else {
      std::fill(v_.begin(), v_.end(), Vec3{});
      dt *= kFireShrink;
      alpha = kFireAlpha;
      positive = 0;
    }
    move(dt);
    zone_.forward_positions();
    // Every process knows the largest move since the lists: they stay
    // right while no sphere can have moved half the skin.
    if (moved_ + step_max_ > 0.5 * skin_) build_lists();
    worst = reduce(forces(), power, vn, fn);
  }
  return worst;
}

double SoftRelaxation::deepest(int k) const
{
  if (slot_[static_cast<std::size_t>(k)] < 0) return 0;
  const std::size_t m = static_cast<std::size_t>(slot_[static_cast<std::size_t>(k)]);
  const ZoneBody &b = zone_.bodies[static_cast<std::size_t>(k)];
  double most = 0;
  for (const Neighbour &n : near_[m]) {
    const ZoneBody &o = zone_.bodies[static_cast<std::size_t>(n.j)];
    if (!o.present) continue;
    const double ri = radius(b), rj = radius(o);
    most = std::max(most, pair_overlap(b.x, ri, o.x, rj, n.allowed) / std::min(ri, rj));
  }
  return most;
}

double SoftRelaxation::worst_at_full_size(double above, std::int64_t &count) const
{
  double worst = 0;
  count = 0;
  for (std::size_t m = 0; m < zone_.moving.size(); ++m) {
    const ZoneBody &b = zone_.bodies[static_cast<std::size_t>(zone_.moving[m])];
    if (!b.present) continue;
    bool exact = true;
    for (const Neighbour &n : near_[m]) {
      const ZoneBody &o = zone_.bodies[static_cast<std::size_t>(n.j)];
      if (!o.present) continue;
      const double overlap = pair_overlap(b.x, b.R, o.x, o.R, n.allowed);
      worst = std::max(worst, overlap / rmin_);
      exact = exact && !(overlap > above * std::min(b.R, o.R));
    }
    if (!exact) count++;
  }
  return worst;
}

}    // namespace reinforce
