#include "reinforce_regrowth_zone.h"

#include "reinforce_cell_grid.h"

#include <algorithm>
#include <cmath>
#include <tuple>
#include <unordered_map>

namespace reinforce {

namespace {

// The flags a body's owner sends its ghosts.
enum : int { kPresent = 1, kMovable = 2, kGrowing = 4, kPacking = 8 };

int flags_of(const ZoneBody &b)
{
  return (b.present ? kPresent : 0) | (b.movable ? kMovable : 0) | (b.growing ? kGrowing : 0) |
         (b.packing ? kPacking : 0);
}

void set_flags(ZoneBody &b, int flags)
{
  b.present = flags & kPresent;
  b.movable = flags & kMovable;
  b.growing = flags & kGrowing;
  b.packing = flags & kPacking;
}

// The distance from x to the nearest seed (or a periodic image of one)
// within `range`, else +infinity.
class SeedDistance {
public:
  SeedDistance(const std::vector<Seed> &seeds, double range, const Domain &domain)
      : range_(range), grid_(range)
  {
    Domain around = domain;
    for (int d = 0; d < 3; ++d) {
      around.view_lo[d] = domain.lo[d] - range;
      around.view_hi[d] = domain.hi[d] + range;
    }
    for (const Seed &s : seeds)
      for (const Vec3 &image : images_in_view(s.x, around, true)) {
        grid_.insert(image, static_cast<int>(points_.size()));
        points_.push_back(image);
      }
  }
  double operator()(Vec3 x) const
  {
    double nearest = INFINITY;
    grid_.for_each_near(x, range_, [&](int k) {
      nearest = std::min(nearest, norm(points_[static_cast<std::size_t>(k)] - x));
    });
    return nearest < range_ ? nearest : INFINITY;
  }

private:
  double range_;
  CellGrid grid_;
  std::vector<Vec3> points_;
};

// Wholly inside the box's faces in its non-periodic dimensions.
bool inside_faces(const AtomArrays &a, int i, const Domain &domain)
{
  for (int d = 0; d < 3; ++d)
    if (!domain.periodic[d] &&
        (a.x[i][d] - a.radius[i] < domain.lo[d] || a.x[i][d] + a.radius[i] > domain.hi[d]))
      return false;
  return true;
}

bool is_matrix(const AtomArrays &a, int i)
{
  return (a.mask[i] & a.group_bit) && !(a.mask[i] & (a.rebar_bit | a.frozen_bits));
}

}    // namespace

Zone::Zone(HostHooks &host, const AtomArrays &a, const std::vector<Seed> &seeds,
           const ZoneShape &shape, const Domain &domain)
    : host_(host)
{
  const SeedDistance seed_distance(seeds, std::max(shape.reach, shape.width), domain);
  std::vector<double> nearest(static_cast<std::size_t>(a.nall));
  for (int i = 0; i < a.nall; ++i)
    nearest[i] = seed_distance(Vec3{a.x[i][0], a.x[i][1], a.x[i][2]});
  // Each owner decides its atoms' radius and flags; the ghosts learn them.
  std::unordered_map<std::int64_t, const Seed *> seed_of;
  for (const Seed &s : seeds) seed_of[s.id] = &s;
  rows_.assign(static_cast<std::size_t>(a.nall) * 2, 0.0);
  for (int i = 0; i < a.nlocal; ++i) {
    ZoneBody b;
    b.R = a.radius[i];
    b.present = true;
    const auto s = seed_of.find(a.id(i));
    if (s != seed_of.end()) {
      const Seed &seed = *s->second;
      const bool vacant = a.pending[i] != 0;
      b.present = seed.kept || !vacant;
      b.movable = b.present;
      b.growing = seed.kept;
      b.packing = !seed.kept;    // a shrunk one left shrunk is a sphere of the packing again
      if (seed.kept) b.R = seed.R;
    } else if (is_matrix(a, i)) {
      // One that pokes through a box face stays: where it moved, it would
      // have to be wholly inside.
      b.movable = nearest[i] < shape.width && inside_faces(a, i, domain);
    }
    rows_[2 * i] = b.R;
    rows_[2 * i + 1] = flags_of(b);
  }
  host_.forward(rows_, 2, false);
  for (int i = 0; i < a.nall; ++i) {
    if (!(nearest[i] < shape.reach)) continue;
    ZoneBody b;
    b.x0 = Vec3{a.x[i][0], a.x[i][1], a.x[i][2]};
    b.R = rows_[2 * i];
    set_flags(b, static_cast<int>(rows_[2 * i + 1]));
    b.id = a.id(i);
    b.local = i;
    b.owned = i < a.nlocal;
    b.rebar = (a.mask[i] & a.rebar_bit) != 0;
    if (b.owned && b.movable) {
      b.w = b.growing ? 1.0 : std::max(0.0, 1 - nearest[i] / shape.width);
      b.cap = shape.cap * b.w;
      moving.push_back(static_cast<int>(bodies.size()));
    }
    if (!b.present) b.movable = false;
    bodies.push_back(b);
    x.push_back(b.x0);
  }
  by_id_.resize(bodies.size());
  for (std::size_t k = 0; k < bodies.size(); ++k) by_id_[k] = static_cast<int>(k);
  std::sort(by_id_.begin(), by_id_.end(),
            [&](int p, int q) { return bodies[p].id < bodies[q].id; });
  find_bars(shape.pull_range);
  rows_.assign(static_cast<std::size_t>(a.nall) * 3, 0.0);
}

// Each owned movable matrix sphere's nearest rebar sphere within `range`
// (its owner sees every one: the ghosts reach that far).
void Zone::find_bars(double range)
{
  CellGrid grid(range);
  double largest = 0;
  for (std::size_t k = 0; k < bodies.size(); ++k)
    if (bodies[k].rebar) {
      grid.insert(bodies[k].x0, static_cast<int>(k));
      largest = std::max(largest, bodies[k].R);
    }
  for (int m : moving) {
    ZoneBody &b = bodies[static_cast<std::size_t>(m)];
    if (b.growing) continue;
    double nearest = range;
    // Every bar whose surface lies within range (the grid may offer more:
    // the test below decides, the same on every process).
    grid.for_each_near(b.x0, range + largest, [&](int k) {
      const ZoneBody &o = bodies[static_cast<std::size_t>(k)];
      const double gap = norm(o.x0 - b.x0) - o.R;
      if (gap < nearest || (gap == nearest && b.bar >= 0 && o.id < bodies[b.bar].id)) {
        nearest = gap;
        b.bar = k;
      }
    });
  }
}

void Zone::forward_positions()
{
  for (int m : moving) {
    const int row = 3 * bodies[static_cast<std::size_t>(m)].local;
    for (int d = 0; d < 3; ++d) rows_[row + d] = x[m][d];
  }
  host_.forward(rows_, 3, true);
  for (std::size_t k = 0; k < bodies.size(); ++k) {
    const ZoneBody &b = bodies[k];
    if (!b.owned && b.movable) x[k] = Vec3{rows_[3 * b.local], rows_[3 * b.local + 1], rows_[3 * b.local + 2]};
  }
}

void Zone::forward_flags()
{
  for (const ZoneBody &b : bodies)
    if (b.owned) rows_[3 * b.local] = flags_of(b);
  host_.forward(rows_, 1, false);
  for (ZoneBody &b : bodies)
    if (!b.owned) set_flags(b, static_cast<int>(rows_[3 * b.local]));
}

std::vector<int> Zone::copies_of(std::int64_t id) const
{
  const auto lo = std::lower_bound(by_id_.begin(), by_id_.end(), id,
                                   [&](int k, std::int64_t v) { return bodies[k].id < v; });
  std::vector<int> out;
  for (auto it = lo; it != by_id_.end() && bodies[*it].id == id; ++it) out.push_back(*it);
  return out;
}

}    // namespace reinforce
