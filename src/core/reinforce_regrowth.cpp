#include "reinforce_regrowth.h"

#include "reinforce_cell_grid.h"

#include <algorithm>
#include <cmath>
#include <tuple>
#include <unordered_map>

namespace reinforce {

namespace {

// A seed starts at this share of its radius, where it was, and grows to
// its own in kGrowthSteps equal steps, each followed by at most
// kSweepsPerStep sweeps of its zone (fewer once the largest overlap is
// below kSettled of a radius: the next step makes new ones anyway); then
// at most kFinalSweeps, until no overlap exceeds tol.
constexpr double kStartScale = 0.5;
constexpr int kGrowthSteps = 10;
constexpr int kSweepsPerStep = 8;
constexpr double kSettled = 1e-3;
constexpr int kFinalSweeps = 200;
// A seed tries at most kStarts places to grow from: the least overlapped
// points near where it was.
constexpr std::size_t kStarts = 4;
// A start overlapping more than this share of the seed's radius is not
// tried: the zone cannot absorb that much.
constexpr double kWorstStart = 0.5;
// Settling onto the bars: kSettlePasses passes, the first stepping a
// sphere by kSettleStep of its radius (times its mobility) towards its
// bar, the later ones less. A seed alone moves out of its overlaps in at
// most kAloneSweeps sweeps.
constexpr int kSettlePasses = 30;
constexpr double kSettleStep = 0.1;
constexpr int kAloneSweeps = 30;
// A seed moves at most this share of the width from where it was; a
// matrix sphere at distance d from the nearest seed at most that times
// (1 - d / width): nothing moves at the zone's edge, so it blends into the
// frozen far field, and nothing leaves the zone.
constexpr double kMoveShare = 0.5;
// A moved sphere ends overlapping nothing by more than this share of tol
// (the checks after the fix use tol itself: room for their rounding).
constexpr double kInnerTol = 0.5;

struct Body {
  Vec3 x, x0;
  double R = 0;        // its own radius
  double scale = 1;    // its radius now, over R (below 1 only while a seed grows)
  double w = 0;        // mobility in the current growth: 1 at its seed, towards 0 at the edge
  double cap = 0;      // largest distance from x0
  std::int64_t id = 0;
  bool seed = false, movable = false, rebar = false, present = true;
  bool active = false;    // moves in the current growth
  bool placed = false;    // a seed put back
  double w_zone = 0;      // mobility in the settling: 1 - (distance to the nearest seed) / width
  int bar = -1;           // the nearest rebar sphere (a matrix sphere settles towards it)
};

struct Contact {
  int j = 0;
  // The pair's overlap at the start (non-seed pairs): left as it was
  // while neither moves (the packing's own overlaps are not the fix's).
  double allowed = 0;
};

// The zone of one block's seeds: its bodies (seeds, movable matrix
// spheres, frozen spheres around them), their possible contacts, and the
// growth.
class Zone {
public:
  Zone(const std::vector<Particle> &reads, const std::vector<std::size_t> &seeds, double width,
       const Settings &settings, const Domain &domain)
      : settings_(settings), domain_(domain), width_(width)
  {
    collect(reads, seeds);
    find_contacts();
  }

  // First the zone's matrix settles onto the bars, the seeds taken out:
  // the room the targets left is spread in caps against the bars, too
  // small for a sphere each; settling gathers it away from the bars.
  // Then the seeds one by one, by id: each grows from the least
  // overlapped places near where it was while its zone makes room; one
  // that cannot fit leaves its zone as it found it and is deleted. No
  // matrix sphere is deleted, and a seed placed stays a movable sphere of
  // the zone for the seeds after it.
  std::vector<RoundRecord> run(RegrowthStats &stats)
  {
    delete_displaced(stats);
    std::vector<std::size_t> waiting;
    for (std::size_t i = 0; i < bodies_.size(); ++i)
      if (bodies_[i].seed && bodies_[i].present) {
        waiting.push_back(i);
        bodies_[i].present = false;    // vacant until its turn
      }
    settle_onto_bars(stats);
    for (std::size_t i : waiting) {
      bodies_[i].present = true;
      grow_seed(i, stats);
    }
    return records(stats);
  }

private:
  double radius(const Body &b) const { return b.R * b.scale; }

  // The deepest overlap (over the seed's radius) a sphere of seed s's
  // radius would have at p with the present spheres.
  double overlap_at(std::size_t s, Vec3 p) const
  {
    const Body &seed = bodies_[s];
    double deepest = 0;
    for (const Contact &c : contacts_[s]) {
      const Body &o = bodies_[static_cast<std::size_t>(c.j)];
      if (o.present) deepest = std::max(deepest, seed.R + o.R - norm(p - o.x));
    }
    return deepest / seed.R;
  }

  // Where seed s may start: the points of a lattice (a quarter of its
  // radius apart) within its cap of where it was that overlap least, the
  // least first, admissible, at most kStarts, at least a radius apart.
  std::vector<Vec3> starts(std::size_t s) const
  {
    const Body &seed = bodies_[s];
    const double h = 0.25 * seed.R;
    const int n = static_cast<int>(std::floor(seed.cap / h));
    std::vector<std::pair<double, Vec3>> scored;
    for (int i = -n; i <= n; ++i)
      for (int j = -n; j <= n; ++j)
        for (int k = -n; k <= n; ++k) {
          const Vec3 d{i * h, j * h, k * h};
          if (norm(d) > seed.cap) continue;
          scored.push_back({overlap_at(s, seed.x0 + d), seed.x0 + d});
        }
    std::stable_sort(scored.begin(), scored.end(),
                     [](const std::pair<double, Vec3> &a, const std::pair<double, Vec3> &b) {
                       return a.first < b.first;
                     });
    std::vector<Vec3> out;
    for (const auto &c : scored) {
      if (c.first > kWorstStart) break;
      bool distinct = true;
      for (const Vec3 &o : out) distinct = distinct && norm(o - c.second) >= seed.R;
      if (!distinct || !admissible(seed.x0, c.second, seed.R, domain_, settings_.tol)) continue;
      out.push_back(c.second);
      if (out.size() == kStarts) break;
    }
    return out;
  }

  // True when body i moved to p would overlap a present body (by more
  // than kInnerTol of tol); `normal` then points from the first such body
  // to p.
  bool blocked_at(std::size_t i, Vec3 p, Vec3 &normal) const
  {
    const Body &b = bodies_[i];
    for (const Contact &c : contacts_[i]) {
      const Body &o = bodies_[static_cast<std::size_t>(c.j)];
      if (!o.present) continue;
      const double dist = norm(p - o.x);
      if (b.R + o.R - dist > kInnerTol * settings_.tol * std::min(b.R, o.R)) {
        normal = dist > 0 ? (1 / dist) * (p - o.x) : Vec3{1, 0, 0};
        return true;
      }
    }
    return false;
  }

  // Body i moved by d, if that leaves it within its cap, admissible and
  // clear of every present body.
  bool step_to(std::size_t i, Vec3 d, Vec3 &normal)
  {
    Body &b = bodies_[i];
    const Vec3 p = b.x + d;
    if (norm(p - b.x0) > b.cap || !admissible(b.x, p, b.R, domain_, settings_.tol)) {
      normal = Vec3{};
      return false;
    }
    if (blocked_at(i, p, normal)) return false;
    b.x = p;
    return true;
  }

  // The zone's matrix (the seeds out) settles onto the bars as hard
  // spheres: each, by id, steps towards its bar, or slides along the
  // sphere that blocks it, and only to where it overlaps nothing; the
  // steps shrink pass by pass. The room the targets left in caps against
  // the bars gathers away from them, where a seed can take it, and the
  // layer against the bars gets dense as in a packing grown around them.
  void settle_onto_bars(RegrowthStats &stats)
  {
    for (int pass = 0; pass < kSettlePasses; ++pass) {
      stats.sweeps++;
      const double share = kSettleStep * (1 - static_cast<double>(pass) / kSettlePasses);
      for (std::size_t i = 0; i < bodies_.size(); ++i) {
        Body &b = bodies_[i];
        if (!b.movable || b.seed || !b.present || b.bar < 0) continue;
        const Body &bar = bodies_[static_cast<std::size_t>(b.bar)];
        const Vec3 to_bar = bar.x - b.x;
        const double gap = norm(to_bar) - bar.R - b.R;
        const double step = std::min(share * b.R * b.w_zone, gap);
        if (!(step > 1e-3 * b.R)) continue;
        const Vec3 d = (step / norm(to_bar)) * to_bar;
        Vec3 n;
        if (step_to(i, d, n)) continue;
        const Vec3 slide = d - dot(d, n) * n;
        if (norm(slide) > 1e-3 * b.R) step_to(i, (step / norm(slide)) * slide, n);
      }
    }
  }

  // Seed s alone (everything else held) moved out of its overlaps from
  // p: true when it ends clear.
  bool fits_alone(std::size_t s, Vec3 p, RegrowthStats &stats)
  {
    Body &seed = bodies_[s];
    seed.x = p;
    seed.w = 1;
    active_.assign(1, s);
    seed.active = true;
    bool clear = false;
    for (int k = 0; k < kAloneSweeps && !clear; ++k)
      clear = sweep(stats) <= kInnerTol * settings_.tol;
    seed.active = false;
    return clear && excess_of(s) == 0;
  }

  // Seed s goes to the first of its starts where it fits alone; else it
  // grows from the best one while its zone makes room; a failed try leaves
  // the zone as it was.
  void grow_seed(std::size_t s, RegrowthStats &stats)
  {
    Body &seed = bodies_[s];
    const std::vector<Vec3> places = starts(s);
    bool clear = false;
    for (std::size_t k = 0; k < places.size() && !clear; ++k)
      clear = fits_alone(s, places[k], stats);
    if (!clear && !places.empty()) {
      seed.x = places.front();
      clear = try_growth(s, stats);
    }
    if (!clear) seed.x = seed.x0;
    seed.present = clear;
    seed.placed = clear;
  }

  bool try_growth(std::size_t s, RegrowthStats &stats)
  {
    Body &seed = bodies_[s];
    // The zone of this seed: the movable spheres within the width of it.
    active_.clear();
    active_.push_back(s);
    for (std::size_t i = 0; i < bodies_.size(); ++i) {
      Body &b = bodies_[i];
      if (i == s || !b.movable || !b.present || (b.seed && !b.placed)) continue;
      const double d = norm(b.x - seed.x);
      if (!(d < width_)) continue;
      b.w = 1 - d / width_;
      active_.push_back(i);
    }
    seed.w = 1;
    saved_.clear();
    for (std::size_t i : active_) {
      bodies_[i].active = true;
      saved_.push_back(bodies_[i].x);
    }
    for (int step = 0; step <= kGrowthSteps; ++step) {
      seed.scale = kStartScale + (1 - kStartScale) * step / kGrowthSteps;
      for (int k = 0; k < kSweepsPerStep; ++k)
        if (sweep(stats) < kSettled) break;
    }
    bool clear = false;
    for (int k = 0; k < kFinalSweeps && !clear; ++k)
      clear = sweep(stats) <= kInnerTol * settings_.tol;
    for (std::size_t i : active_)
      if (clear && excess_of(i) > 0) clear = false;
    for (std::size_t n = 0; n < active_.size(); ++n) {
      Body &b = bodies_[active_[n]];
      b.active = false;
      if (!clear) b.x = saved_[n];
    }
    return clear;
  }

  void collect(const std::vector<Particle> &reads, const std::vector<std::size_t> &seeds)
  {
    std::vector<std::size_t> seed_list(seeds);
    std::sort(seed_list.begin(), seed_list.end(),
              [&](std::size_t a, std::size_t b) { return reads[a].id < reads[b].id; });
    // Only the nearest seed within the width matters (cells of that size).
    CellGrid near_seed(width_);
    for (std::size_t s : seed_list) near_seed.insert_around(reads[s].x, static_cast<int>(s));
    std::unordered_map<std::int64_t, int> copies;
    for (std::size_t k = 0; k < reads.size(); ++k) {
      const Particle &p = reads[k];
      if (p.role == Role::Target) continue;    // vacant (other blocks' targets, images)
      double nearest = INFINITY;
      near_seed.for_each_in_cell(p.x, [&](int s) {
        nearest = std::min(nearest, norm(reads[static_cast<std::size_t>(s)].x - p.x));
      });
      Body b;
      b.x = b.x0 = p.x;
      b.R = p.r;
      b.id = p.id;
      b.rebar = p.role == Role::Rebar;
      b.movable = p.role == Role::Matrix && p.pushable && !p.other_rebar && nearest < width_;
      if (b.movable) {
        b.w_zone = 1 - nearest / width_;
        b.cap = kMoveShare * width_ * b.w_zone;
        copies[b.id]++;
      }
      bodies_.push_back(b);
    }
    // An atom seen twice here (periodic images) stays where it is: moving
    // one copy would leave the other behind.
    for (Body &b : bodies_)
      if (b.movable && copies[b.id] > 1) b.movable = false;
    for (std::size_t s : seed_list) {
      Body b;
      b.x = b.x0 = reads[s].x;
      b.R = reads[s].r;
      b.id = reads[s].id;
      b.seed = b.movable = true;
      b.cap = kMoveShare * width_;
      bodies_.push_back(b);
    }
    // Sweeps go by id (then place: frozen images share one), whatever the
    // order of `reads`.
    std::sort(bodies_.begin(), bodies_.end(), [](const Body &a, const Body &b) {
      return std::tie(a.id, a.x0.x, a.x0.y, a.x0.z) < std::tie(b.id, b.x0.x, b.x0.y, b.x0.z);
    });
    std::vector<int> bars;
    for (std::size_t k = 0; k < bodies_.size(); ++k)
      if (bodies_[k].rebar) bars.push_back(static_cast<int>(k));
    for (Body &b : bodies_) {
      if (!b.movable || b.seed) continue;
      double nearest = INFINITY;
      for (int k : bars) {
        const Body &bar = bodies_[static_cast<std::size_t>(k)];
        const double gap = norm(b.x0 - bar.x0) - bar.R;
        if (gap < nearest) {
          nearest = gap;
          b.bar = k;
        }
      }
    }
  }

  void find_contacts()
  {
    double largest = 0, cap = 0;
    for (const Body &b : bodies_) {
      largest = std::max(largest, b.R);
      cap = std::max(cap, b.cap);
    }
    CellGrid grid(2 * (largest + cap));
    for (std::size_t k = 0; k < bodies_.size(); ++k)
      grid.insert(bodies_[k].x0, static_cast<int>(k));
    contacts_.assign(bodies_.size(), {});
    for (std::size_t i = 0; i < bodies_.size(); ++i) {
      const Body &b = bodies_[i];
      if (!b.movable) continue;
      grid.for_each_near(b.x0, b.R + largest + b.cap + cap, [&](int j) {
        if (static_cast<std::size_t>(j) == i) return;
        const Body &o = bodies_[static_cast<std::size_t>(j)];
        // Neither can come closer than this: caps bound their moves.
        const double reach = b.R + o.R + b.cap + o.cap;
        if (!(norm(b.x0 - o.x0) < reach)) return;
        Contact c;
        c.j = j;
        if (!b.seed && !o.seed) c.allowed = std::max(0.0, b.R + o.R - norm(b.x0 - o.x0));
        contacts_[i].push_back(c);
      });
      std::sort(contacts_[i].begin(), contacts_[i].end(),
                [](const Contact &a, const Contact &c) { return a.j < c.j; });
    }
  }

  // A seed whose centre lies inside a bar sphere is what the bar displaces:
  // deleted before the growth.
  void delete_displaced(RegrowthStats &stats)
  {
    for (std::size_t i = 0; i < bodies_.size(); ++i) {
      Body &b = bodies_[i];
      if (!b.seed) continue;
      for (const Contact &c : contacts_[i]) {
        const Body &o = bodies_[static_cast<std::size_t>(c.j)];
        if (o.rebar && norm(b.x0 - o.x0) < o.R) {
          b.present = false;
          stats.displaced++;
          break;
        }
      }
    }
  }

  // What the pair may overlap: its overlap at the start while neither has
  // moved, else nothing.
  static double allowed(const Body &b, const Body &o, const Contact &c)
  {
    const bool unmoved = b.x.x == b.x0.x && b.x.y == b.x0.y && b.x.z == b.x0.z && o.x.x == o.x0.x &&
                         o.x.y == o.x0.y && o.x.z == o.x0.z;
    return unmoved ? c.allowed : 0;
  }

  // The direction from o to b; for coincident centres one fixed by the ids.
  static Vec3 apart(const Body &b, const Body &o, double dist)
  {
    if (dist > 1e-12 * (b.R + o.R)) return (1 / dist) * (b.x - o.x);
    return Vec3{b.id < o.id ? -1.0 : 1.0, 0, 0};
  }

  // One Gauss-Seidel sweep over the active spheres: each, by id, moves out
  // of its overlaps (its share of each against an active sphere, by
  // mobility; all of it against any other), by half of tol more, then back
  // within its cap; a move the walls, region or box refuse is not made.
  // Returns the largest overlap met (above what is allowed), over the
  // smaller radius.
  double sweep(RegrowthStats &stats)
  {
    stats.sweeps++;
    double worst = 0;
    for (std::size_t i : active_) {
      Body &b = bodies_[i];
      const double ri = radius(b);
      Vec3 shift;
      for (const Contact &c : contacts_[i]) {
        const Body &o = bodies_[static_cast<std::size_t>(c.j)];
        if (!o.present) continue;
        const double rj = radius(o);
        const double dist = norm(b.x - o.x);
        const double excess = ri + rj - dist - allowed(b, o, c);
        if (!(excess > 0)) continue;
        const double small = std::min(ri, rj);
        worst = std::max(worst, excess / small);
        const double share = o.active ? b.w / (b.w + o.w) : 1.0;
        shift = shift + (share * (excess + settings_.tol * small)) * apart(b, o, dist);
      }
      if (norm2(shift) == 0) continue;
      Vec3 to = b.x + shift;
      const double off = norm(to - b.x0);
      if (off > b.cap) to = b.x0 + (b.cap / off) * (to - b.x0);
      if (admissible(b.x, to, b.R, domain_, settings_.tol)) b.x = to;
    }
    return worst;
  }

  // The overlaps of body i above tol (and above what is allowed), summed,
  // over the smaller radius of each pair.
  double excess_of(std::size_t i) const
  {
    const Body &b = bodies_[i];
    double sum = 0;
    for (const Contact &c : contacts_[i]) {
      const Body &o = bodies_[static_cast<std::size_t>(c.j)];
      if (!o.present) continue;
      const double small = std::min(b.R, o.R);
      const double excess = (b.R + o.R - norm(b.x - o.x) - allowed(b, o, c)) / small;
      if (excess > kInnerTol * settings_.tol) sum += excess;
    }
    return sum;
  }

  std::vector<RoundRecord> records(RegrowthStats &stats) const
  {
    std::vector<RoundRecord> out;
    for (std::size_t i = 0; i < bodies_.size(); ++i) {
      const Body &b = bodies_[i];
      if (!b.movable) continue;
      if (!b.present) {
        (b.seed ? stats.deleted : stats.deleted_matrix)++;
        out.push_back({b.id, RecordKind::Deleted, b.x0, b.R});
        if (!b.seed) stats.volume_deleted_matrix += 4.0 / 3.0 * M_PI * b.R * b.R * b.R;
        if (b.seed) stats.seeds++;
        continue;
      }
      if (b.seed) {
        stats.seeds++;
        stats.regrown++;
        stats.volume_regrown += 4.0 / 3.0 * M_PI * b.R * b.R * b.R;
        out.push_back({b.id, RecordKind::Placed, b.x, b.R});
      } else {
        const Vec3 dx = b.x - b.x0;
        if (norm2(dx) == 0) continue;
        stats.moved++;
        stats.max_move = std::max(stats.max_move, norm(dx) / settings_.rmin);
        out.push_back({b.id, RecordKind::Pushed, dx, 0});
      }
      double largest = 0;
      for (const Contact &c : contacts_[i]) {
        const Body &o = bodies_[static_cast<std::size_t>(c.j)];
        if (o.present) largest = std::max(largest, (b.R + o.R - norm(b.x - o.x)) / settings_.rmin);
      }
      stats.max_overlap = std::max(stats.max_overlap, largest);
    }
    return out;
  }

  const Settings &settings_;
  const Domain &domain_;
  double width_;
  std::vector<Body> bodies_;
  std::vector<std::vector<Contact>> contacts_;
  std::vector<std::size_t> active_;    // the current growth's spheres, the seed first
  std::vector<Vec3> saved_;            // where they were before it
};

}    // namespace

RegrowthReach regrowth_reach(double width, double matrix_rmax, double largest_r)
{
  // Movable spheres lie within width of a seed and stay there (the caps);
  // each touches spheres whose centres lie within the two radii of it.
  RegrowthReach reach;
  reach.write = width;
  reach.read = (width + matrix_rmax + largest_r) * (1 + 1e-9);
  return reach;
}

std::vector<RoundRecord> regrow(const std::vector<Particle> &reads,
                                const std::vector<std::size_t> &seeds, double width,
                                const Settings &settings, const Domain &domain,
                                RegrowthStats &stats)
{
  if (seeds.empty()) return {};
  Zone zone(reads, seeds, width, settings, domain);
  return zone.run(stats);
}

}    // namespace reinforce
