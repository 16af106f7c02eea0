#include "reinforce_regrowth_count.h"

#include "reinforce_ball_sample.h"
#include "reinforce_cell_grid.h"
#include "reinforce_round_records.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace reinforce {

namespace {

constexpr int kSeedDoubles = 9;    // id (two halves), x, R, r, depth, inside

// x moved by whole box lengths in the periodic dimensions to the copy
// nearest `near`.
Vec3 nearest_copy(Vec3 x, Vec3 near, const Domain &domain)
{
  for (int d = 0; d < 3; ++d) {
    if (!domain.periodic[d]) continue;
    const double period = domain.hi[d] - domain.lo[d];
    x[d] -= period * std::round((x[d] - near[d]) / period);
  }
  return x;
}

// The rebar spheres this process sees, by a cell grid.
class Bars {
public:
  Bars(const AtomArrays &a) : grid_(1.0)
  {
    for (int i = 0; i < a.nall; ++i)
      if (a.mask[i] & a.rebar_bit) {
        centres_.push_back({a.x[i][0], a.x[i][1], a.x[i][2]});
        radii_.push_back(a.radius[i]);
        largest_ = std::max(largest_, a.radius[i]);
      }
    grid_ = CellGrid(2 * largest_);
    for (std::size_t k = 0; k < centres_.size(); ++k)
      grid_.insert(centres_[k], static_cast<int>(k));
  }
  // The depth of x (to the nearest bar surface within R of it, else
  // +infinity) and the volume of ball (x, R) inside the bars.
  void measure(Vec3 x, double R, double &depth, double &inside) const
  {
    depth = INFINITY;
    std::vector<std::size_t> touching;
    // Only the bars within R + largest: the grid may offer farther ones,
    // and which it offers must not decide (the same on every process).
    grid_.for_each_near(x, R + largest_, [&](int k) {
      const double d = norm(x - centres_[k]);
      if (!(d < R + largest_)) return;
      depth = std::min(depth, d - radii_[k]);
      if (d < R + radii_[k]) touching.push_back(static_cast<std::size_t>(k));
    });
    inside = ball_volume(R) * ball_fraction(x, R, [&](Vec3 p) {
               for (std::size_t k : touching)
                 if (norm2(p - centres_[k]) < radii_[k] * radii_[k]) return true;
               return false;
             });
  }

private:
  CellGrid grid_;
  std::vector<Vec3> centres_;
  std::vector<double> radii_;
  double largest_ = 0;
};

}    // namespace

std::vector<Seed> gather_seeds(HostHooks &host, const AtomArrays &a,
                               const std::vector<ShrunkTarget> &shrunk, const Domain &domain)
{
  std::unordered_map<std::int64_t, const ShrunkTarget *> shrunk_of;
  for (const ShrunkTarget &t : shrunk) shrunk_of[t.id] = &t;
  const Bars bars(a);
  std::vector<double> mine;
  for (int i = 0; i < a.nlocal; ++i) {
    const auto s = shrunk_of.find(a.id(i));
    if (!a.pending[i] && s == shrunk_of.end()) continue;
    Seed seed;
    seed.id = a.id(i);
    const Vec3 at{a.x[i][0], a.x[i][1], a.x[i][2]};
    seed.x = at;
    seed.R = a.radius[i];
    if (s != shrunk_of.end()) {
      seed.x = nearest_copy(s->second->x0, at, domain);
      seed.R = s->second->r0;
      seed.r = a.radius[i];
    }
    bars.measure(seed.x, seed.R, seed.depth, seed.inside);
    seed.x = wrapped_into_box(seed.x, domain);
    put_id(seed.id, mine);
    mine.insert(mine.end(),
                {seed.x.x, seed.x.y, seed.x.z, seed.R, seed.r, seed.depth, seed.inside});
  }
  const std::vector<double> all = host.gather_all(mine);
  std::vector<Seed> seeds;
  for (std::size_t k = 0; k + kSeedDoubles <= all.size(); k += kSeedDoubles) {
    Seed seed;
    if (!read_id(&all[k], seed.id)) host.fail("Fix reinforce/invert: internal error: bad seed id");
    seed.x = {all[k + 2], all[k + 3], all[k + 4]};
    seed.R = all[k + 5];
    seed.r = all[k + 6];
    seed.depth = all[k + 7];
    seed.inside = all[k + 8];
    seeds.push_back(seed);
  }
  std::sort(seeds.begin(), seeds.end(), [](const Seed &p, const Seed &q) { return p.id < q.id; });
  return seeds;
}

void count_kept(std::vector<Seed> &seeds, double share)
{
  double goal = 0;
  std::vector<Seed *> order;
  for (Seed &s : seeds) {
    goal += share * s.inside;
    order.push_back(&s);
  }
  std::stable_sort(order.begin(), order.end(),
                   [](const Seed *p, const Seed *q) { return p->depth < q->depth; });
  double deleted = 0;
  bool deleting = true;
  for (Seed *s : order) {
    const double volume = ball_volume(s->R) - ball_volume(s->r);
    deleting = deleting && deleted + 0.5 * volume < goal;
    s->kept = !deleting;
    if (deleting) deleted += volume;
  }
}

}    // namespace reinforce
