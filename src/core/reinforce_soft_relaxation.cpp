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
  // Whether a move can meet a wall or leave the region: a sphere whose
  // cap (and radius) around where it started lies wholly clear of every
  // wall and inside the region cannot, and is not tested at each step.
  walled_.assign(n, 0);
  for (std::size_t m = 0; m < n; ++m) {
    const ZoneBody &b = bodies[static_cast<std::size_t>(zone_.moving[m])];
    const double reach = b.R + b.cap;
    const bool walls = domain_.walls && !(domain_.walls->distance(b.x0) > reach);
    const bool region = domain_.region && !domain_.region(wrapped_into_box(b.x0, domain_), reach);
    walled_[m] = walls || region;
  }
}

// Each body's radius now (the movable ones at the scale; 0: absent).
void SoftRelaxation::update_radii()
{
  const std::vector<ZoneBody> &bodies = zone_.bodies;
  radius_.resize(bodies.size());
  movable_.resize(bodies.size());
  for (std::size_t k = 0; k < bodies.size(); ++k) {
    const ZoneBody &b = bodies[k];
    radius_[k] = !b.present ? 0.0 : (b.movable ? scale_ * b.R : b.R);
    movable_[k] = b.movable;
  }
  stale_radii_ = false;
}

// Each moving body's neighbours: the present bodies within both radii,
// the skin and a pad of it, in (id, place) order, with what the pair
// overlapped at the start when both are spheres of the packing.
void SoftRelaxation::build_lists()
{
  const std::vector<ZoneBody> &bodies = zone_.bodies;
  const std::vector<Vec3> &x = zone_.x;
  double largest = 0, movable = 0;
  for (const ZoneBody &b : bodies) {
    largest = std::max(largest, b.R);
    if (b.movable) movable = std::max(movable, b.R);
  }
  const double margin = skin_ + kPad * movable;
  CellGrid grid(2 * movable + margin);
  for (std::size_t k = 0; k < bodies.size(); ++k)
    if (bodies[k].present) grid.insert(x[k], static_cast<int>(k));
  for (std::size_t m = 0; m < zone_.moving.size(); ++m) {
    const int i = zone_.moving[m];
    const ZoneBody &b = bodies[static_cast<std::size_t>(i)];
    std::vector<Neighbour> &list = near_[m];
    list.clear();
    built_[m] = x[i];
    if (!b.present) continue;
    grid.for_each_near(x[i], b.R + largest + margin, [&](int j) {
      const ZoneBody &o = bodies[static_cast<std::size_t>(j)];
      if (j == i || !(norm(x[i] - x[j]) < b.R + o.R + margin)) return;
      const double allowed =
          b.packing && o.packing ? std::max(0.0, pair_overlap(b.x0, b.R, o.x0, o.R, 0)) : 0;
      list.push_back({j, allowed});
    });
    std::sort(list.begin(), list.end(),
              [&](const Neighbour &p, const Neighbour &q) { return rank_[p.j] < rank_[q.j]; });
  }
  moved_ = 0;
  stale_ = false;
}

// The forces on the moving bodies (their overlaps, harmonic, unit
// stiffness, summed in (id, place) order; the pull towards their bar).
// Returns the largest overlap here, over the smaller radius.
double SoftRelaxation::forces()
{
  const std::vector<ZoneBody> &bodies = zone_.bodies;
  const std::vector<Vec3> &x = zone_.x;
  double worst = 0;
  for (std::size_t m = 0; m < zone_.moving.size(); ++m) {
    const int i = zone_.moving[m];
    const double ri = radius_[i];
    Vec3 F;
    if (ri > 0) {
      const Vec3 xi = x[i];
      for (const Neighbour &n : near_[m]) {
        const double rj = radius_[n.j];
        if (!(rj > 0)) continue;
        double contact = ri + rj - n.allowed;
        // Padded: a pair of movable spheres, unless the packing had it
        // overlapping by half a pad or more at the start (such a contact
        // keeps its own overlap, never more: opening it would need room a
        // settled packing has not got).
        const double pad = pad_ * std::min(ri, rj);
        if (pad > 0 && movable_[n.j] && n.allowed < 0.5 * pad) contact += pad;
        const Vec3 d = xi - x[n.j];
        const double d2 = norm2(d);
        if (d2 >= contact * contact) continue;
        const double dist = std::sqrt(d2);
        const double delta = contact - dist;
        worst = std::max(worst, delta / ri);
        // Coincident centres: a direction fixed by the ids, the same on
        // every process.
        if (dist > 1e-12 * (ri + rj))
          F = F + (delta / dist) * d;
        else
          F = F + Vec3{bodies[i].id < bodies[n.j].id ? -delta : delta, 0, 0};
      }
      const ZoneBody &b = bodies[static_cast<std::size_t>(i)];
      if (pull_ > 0 && b.bar >= 0) {
        const Vec3 to_bar = x[b.bar] - xi;
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
  double moved = 0;
  for (std::size_t m = 0; m < f_.size(); ++m) {
    p.add(dot(f_[m], v_[m]));
    vv.add(norm2(v_[m]));
    ff.add(norm2(f_[m]));
    moved = std::max(moved, norm2(zone_.x[zone_.moving[m]] - built_[m]));
  }
  std::vector<double> sums;
  for (const ExactSum *s : {&p, &vv, &ff}) {
    const auto limbs = s->limbs();
    sums.insert(sums.end(), limbs.begin(), limbs.end());
  }
  std::vector<double> maxima{worst, std::sqrt(moved)};
  host_.sum_and_max(sums, maxima);
  power = ExactSum::from_limbs(&sums[0], unit);
  vnorm = std::sqrt(std::max(0.0, ExactSum::from_limbs(&sums[ExactSum::kLimbs], unit)));
  fnorm = std::sqrt(std::max(0.0, ExactSum::from_limbs(&sums[2 * ExactSum::kLimbs], unit)));
  moved_ = maxima[1];
  return maxima[0];
}

// One step of each moving body: within its cap (sliding along it), along
// the box faces, and not where the walls or region refuse it.
void SoftRelaxation::move(double dt)
{
  for (std::size_t m = 0; m < zone_.moving.size(); ++m) {
    const int i = zone_.moving[m];
    const ZoneBody &b = zone_.bodies[static_cast<std::size_t>(i)];
    if (!b.present) continue;
    Vec3 &x = zone_.x[i];
    Vec3 &v = v_[m];
    v = v + dt * f_[m];
    Vec3 d = dt * v;
    const double dn = norm(d);
    if (dn > kFireStep * b.R) d = (kFireStep * b.R / dn) * d;
    Vec3 to = x + d;
    const double off = norm(to - b.x0);
    if (off > b.cap) {
      const Vec3 n = (1 / off) * (to - b.x0);
      to = b.x0 + b.cap * n;
      const double out = dot(v, n);
      if (out > 0) v = v - out * n;
    }
    // Wholly inside the box faces (a sphere of the packing that pokes
    // through one does not move: Zone).
    for (int a = 0; a < 3; ++a) {
      if (domain_.periodic[a]) continue;
      const double lo = domain_.lo[a] + b.R, hi = domain_.hi[a] - b.R;
      if (to[a] < lo) {
        to[a] = lo;
        v[a] = 0;
      } else if (to[a] > hi) {
        to[a] = hi;
        v[a] = 0;
      }
    }
    if (walled_[m] && !admissible(x, to, b.R, domain_, tol_)) {
      v = Vec3{};
      continue;
    }
    x = to;
  }
}

double SoftRelaxation::run(int steps, double done)
{
  double dt = kFireDt, alpha = kFireAlpha;
  int positive = 0;
  std::fill(v_.begin(), v_.end(), Vec3{});
  if (stale_radii_) update_radii();
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
  const int m = slot_[static_cast<std::size_t>(k)];
  if (m < 0 || !(radius_[k] > 0)) return 0;
  const double ri = radius_[k];
  double most = 0;
  for (const Neighbour &n : near_[static_cast<std::size_t>(m)]) {
    const double rj = radius_[n.j];
    if (!(rj > 0)) continue;
    most = std::max(most, pair_overlap(zone_.x[k], ri, zone_.x[n.j], rj, n.allowed) / ri);
  }
  return most;
}

double SoftRelaxation::worst_at_full_size(double above, std::int64_t &count) const
{
  const std::vector<ZoneBody> &bodies = zone_.bodies;
  double worst = 0;
  count = 0;
  for (std::size_t m = 0; m < zone_.moving.size(); ++m) {
    const int i = zone_.moving[m];
    const ZoneBody &b = bodies[static_cast<std::size_t>(i)];
    if (!b.present) continue;
    bool exact = true;
    for (const Neighbour &n : near_[m]) {
      const ZoneBody &o = bodies[static_cast<std::size_t>(n.j)];
      if (!o.present) continue;
      const double overlap = pair_overlap(zone_.x[i], b.R, zone_.x[n.j], o.R, n.allowed);
      worst = std::max(worst, overlap / rmin_);
      exact = exact && !(overlap > above * std::min(b.R, o.R));
    }
    if (!exact) count++;
  }
  return worst;
}

}    // namespace reinforce
