#include "reinforce_soft_relaxation.h"

#include "reinforce_boundaries.h"
#include "reinforce_cell_grid.h"
#include "reinforce_regrowth_policy.h"

#include <algorithm>
#include <cmath>

namespace reinforce {

using namespace regrowth_policy;

SoftRelaxation::SoftRelaxation(std::vector<Body> &bodies, const std::vector<std::size_t> &active,
                               const Domain &domain, double tol)
    : bodies_(bodies), active_(active), domain_(domain), tol_(tol)
{
}

// The lists' skin from the largest movable sphere, and room for a list per
// body, once the zone has its bodies.
void SoftRelaxation::size_lists()
{
  if (near_.size() == bodies_.size()) return;
  double largest = 0;
  largest_ = 0;
  for (const Body &b : bodies_) {
    if (b.movable) largest = std::max(largest, b.R);
    largest_ = std::max(largest_, b.R);
  }
  skin_ = kSkin * largest;
  near_.assign(bodies_.size(), {});
  built_.assign(bodies_.size(), Vec3{});
}

// The forces on the active spheres: their overlaps (harmonic, unit
// stiffness) and the pull towards their bar, if any. Returns the largest
// overlap, over the smaller radius.
double SoftRelaxation::forces(std::vector<Vec3> &f) const
{
  double worst = 0;
  for (std::size_t i : active_) {
    const Body &b = bodies_[i];
    const double ri = radius(b);
    Vec3 F;
    for (const Contact &c : near_[i]) {
      const Body &o = bodies_[static_cast<std::size_t>(c.j)];
      if (!o.present) continue;
      const double rj = radius(o);
      double sum = ri + rj - c.allowed;    // contact, less the pair's own overlap
      // Padded between two moving spheres only: one held by its cap or a
      // wall against a frozen sphere it touches could never make the pad.
      if (pad_ > 0 && o.active) sum += pad_ * std::min(ri, rj);
      const double d2 = norm2(b.x - o.x);
      if (d2 >= sum * sum) continue;
      const double dist = std::sqrt(d2);
      const double delta = sum - dist;
      worst = std::max(worst, delta / std::min(ri, rj));
      F = F + delta * apart(b, o, dist);
    }
    if (pull_ > 0 && !b.seed && b.bar >= 0) {
      const Vec3 to_bar = bodies_[static_cast<std::size_t>(b.bar)].x - b.x;
      const double n = norm(to_bar);
      if (n > 0) F = F + (pull_ * b.R * b.w_zone / n) * to_bar;
    }
    f[i] = F;
  }
  return worst;
}

// The neighbour lists of the active spheres: the present spheres within
// the two radii and skin_ of them that can touch them (can_touch), by
// index; found in a cell grid of where the spheres are now
// (a zone's possible contacts reach across the caps: many times more).
void SoftRelaxation::build_near()
{
  CellGrid grid(2 * largest_ + skin_);
  for (std::size_t k = 0; k < bodies_.size(); ++k)
    if (bodies_[k].present) grid.insert(bodies_[k].x, static_cast<int>(k));
  for (std::size_t i : active_) {
    near_[i].clear();
    const Body &b = bodies_[i];
    grid.for_each_near(b.x, b.R + largest_ + skin_, [&](int j) {
      const Body &o = bodies_[static_cast<std::size_t>(j)];
      if (static_cast<std::size_t>(j) == i || !(norm(b.x - o.x) < b.R + o.R + skin_) ||
          !can_touch(b, o))
        return;
      near_[i].push_back({j, allowed_overlap(b, o)});
    });
    std::sort(near_[i].begin(), near_[i].end(),
              [](const Contact &a, const Contact &c) { return a.j < c.j; });
    built_[i] = b.x;
  }
}

// FIRE over the active spheres until the largest overlap is at most
// `done` (over the smaller radius), at most `iters` steps. A sphere
// stays within its cap (sliding along it), slides along the box faces,
// and does not make a move the walls or region refuse. Returns the
// largest overlap.
double SoftRelaxation::run(int iters, double done, std::int64_t &steps)
{
  double dt = kFireDt, alpha = kFireAlpha;
  int positive = 0;
  size_lists();
  std::vector<Vec3> f(bodies_.size()), v(bodies_.size());
  build_near();
  double worst = forces(f);
  for (int it = 0; it < iters && worst > done; ++it) {
    steps++;
    double power = 0, vn = 0, fn = 0;
    for (std::size_t i : active_) {
      power += dot(f[i], v[i]);
      vn += norm2(v[i]);
      fn += norm2(f[i]);
    }
    vn = std::sqrt(vn);
    fn = std::sqrt(fn);
    if (power > 0) {
      if (fn > 0)
        for (std::size_t i : active_) v[i] = (1 - alpha) * v[i] + (alpha * vn / fn) * f[i];
      if (++positive > kFireDelay) {
        dt = std::min(dt * kFireGrow, kFireDtMax);
        alpha *= kFireAlphaDecay;
      }
    } else {
      for (std::size_t i : active_) v[i] = Vec3{};
      dt *= kFireShrink;
      alpha = kFireAlpha;
      positive = 0;
    }
    bool rebuild = false;
    for (std::size_t i : active_) {
      Body &b = bodies_[i];
      v[i] = v[i] + dt * f[i];
      Vec3 d = dt * v[i];
      const double dn = norm(d);
      if (dn > kFireStep * b.R) d = (kFireStep * b.R / dn) * d;
      Vec3 to = b.x + d;
      const double off = norm(to - b.x0);
      if (off > b.cap) {
        const Vec3 n = (1 / off) * (to - b.x0);
        to = b.x0 + b.cap * n;
        const double out = dot(v[i], n);
        if (out > 0) v[i] = v[i] - out * n;
      }
      for (int a = 0; a < 3; ++a) {
        if (domain_.periodic[a]) continue;
        const double lo = domain_.lo[a] + b.R, hi = domain_.hi[a] - b.R;
        if (to[a] < lo && b.x[a] >= lo) {
          to[a] = lo;
          v[i][a] = 0;
        } else if (to[a] > hi && b.x[a] <= hi) {
          to[a] = hi;
          v[i][a] = 0;
        }
      }
      if (!admissible(b.x, to, b.R, domain_, tol_)) {
        v[i] = Vec3{};
        continue;
      }
      b.x = to;
      if (norm(b.x - built_[i]) > 0.5 * skin_) rebuild = true;
    }
    if (rebuild) build_near();
    worst = forces(f);
  }
  return worst;
}

}    // namespace reinforce
