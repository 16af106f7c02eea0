#include "reinforce_regrowth.h"

#include "reinforce_ball_sample.h"
#include "reinforce_cell_grid.h"
#include "reinforce_regrowth_zone.h"
#include "reinforce_soft_relaxation.h"

#include <algorithm>
#include <cmath>

namespace reinforce {

namespace {

using namespace regrowth_policy;

// How seeds grow together: from `start` of their radius in `stages` equal
// stages of at most `stage_iters` FIRE steps; in grow balance the zone's
// matrix shrinks and grows with them, pulled towards the bars (`pull` for
// `pull_iters` steps a stage) while the radii are below `pull_until`.
struct GrowthPlan {
  double start;
  int stages;
  int stage_iters;
  double pull, pull_until;
  int pull_iters;
};
constexpr GrowthPlan kTogether{kStartScale, kGrowthSteps, kStepIters, 0, 0, 0};
constexpr GrowthPlan kBalance{kBalanceStart, kBalanceStages,    kBalanceStageIters,
                              kBalancePull,  kBalancePullUntil, kBalancePullIters};

// The zone of one block's seeds: its bodies (seeds, movable matrix
// spheres, frozen spheres around them), their possible contacts, and the
// growth.
class Zone {
public:
  Zone(const std::vector<Particle> &reads, const std::vector<std::size_t> &seeds, double width,
       const Settings &settings, const Domain &domain)
      : settings_(settings), domain_(domain), width_(width)
  {
    bodies_ = zone_bodies(reads, seeds, width);
    contacts_ = zone_contacts(bodies_);
  }

  // First the zone's matrix settles onto the bars, the seeds taken out:
  // the room the targets left is spread in caps against the bars, too
  // small for a sphere each; settling (hard spheres), then compaction
  // (soft spheres pulled towards the bars, relaxed) gather it away from
  // the bars and make the layer against them dense. Then the seeds: all
  // together (grow_together), those the zone cannot hold given up; or one
  // by one, by id (grow_seed), each from the least overlapped places near
  // where it was while the whole zone relaxes (FIRE), one that cannot fit
  // leaving the zone as it found it, deleted. A shrunk seed's shrunk
  // sphere stays where the seed is not put back. No matrix sphere is
  // deleted, and a seed placed stays a movable sphere of the zone for the
  // seeds after it.
  std::vector<RoundRecord> run(RegrowthStats &stats)
  {
    if (settings_.grow_balance) return rebuild(stats);
    return regrow_around(settings_.grow_together, stats);
  }

  // Whether the rebuilt zone (grow balance) jammed and went back: no
  // records, the block as the relocation left it.
  bool jammed() const { return jammed_; }

  // The seeds the relocation placed shrunk left shrunk: only those without
  // a place are grown back.
  void leave_shrunk()
  {
    for (Body &seed : bodies_)
      if (seed.seed && seed.twin >= 0) seed.present = false;
  }

private:
  // The zone's matrix settled and compacted around the vacant seeds, which
  // then grow back together (`together`) or one by one.
  std::vector<RoundRecord> regrow_around(bool together, RegrowthStats &stats)
  {
    delete_displaced(stats);
    std::vector<std::size_t> waiting;
    for (std::size_t i = 0; i < bodies_.size(); ++i)
      if (bodies_[i].seed && bodies_[i].present) {
        waiting.push_back(i);
        bodies_[i].present = false;    // vacant until its turn
      }
    settle_onto_bars(stats);
    compact(stats);
    if (together) waiting = grow_together(waiting, stats);
    for (std::size_t i : waiting) {
      const int twin = bodies_[i].twin;
      // A shrunk sphere that may not move (beyond the zone, an image) stays.
      if (twin >= 0 && !bodies_[static_cast<std::size_t>(twin)].movable) continue;
      if (twin >= 0) bodies_[static_cast<std::size_t>(twin)].present = false;
      bodies_[i].present = true;
      grow_seed(i, stats);
      if (twin >= 0 && !bodies_[i].placed) bodies_[static_cast<std::size_t>(twin)].present = true;
    }
    return records(stats);
  }

  // grow balance: the block's seeds deleted, the deepest centre first (a
  // centre inside a bar sphere first of all), until the deleted volume
  // is nearest kBalanceShare times the seeds' volume inside the bars; the
  // rest grown back together with the whole zone (kBalance), from where
  // they were pushed out of the bars. A shrunk seed deleted stays shrunk
  // where the relocation placed it (its volume short of its own counts).
  std::vector<RoundRecord> rebuild(RegrowthStats &stats)
  {
    struct Candidate {
      double depth;    // centre to the nearest bar surface (< 0: inside)
      std::size_t i;
    };
    std::vector<Candidate> order;
    const std::int64_t displaced_before = stats.displaced;
    double goal = 0;
    for (std::size_t i = 0; i < bodies_.size(); ++i) {
      Body &seed = bodies_[i];
      if (!seed.seed) continue;
      seed.present = false;    // vacant until it grows
      // A shrunk sphere that may not move (beyond the zone, an image) stays.
      if (seed.twin >= 0 && !bodies_[static_cast<std::size_t>(seed.twin)].movable) continue;
      double depth = INFINITY;
      std::vector<std::size_t> bars;
      for (const Contact &c : contacts_[i]) {
        const Body &o = bodies_[static_cast<std::size_t>(c.j)];
        if (!o.rebar) continue;
        depth = std::min(depth, norm(seed.x0 - o.x0) - o.R);
        if (norm(seed.x0 - o.x0) < seed.R + o.R) bars.push_back(static_cast<std::size_t>(c.j));
      }
      const double inside = ball_fraction(seed.x0, seed.R, [&](Vec3 p) {
        for (std::size_t b : bars)
          if (norm2(p - bodies_[b].x0) < bodies_[b].R * bodies_[b].R) return true;
        return false;
      });
      goal += kBalanceShare * inside * ball_volume(seed.R);
      order.push_back({depth, i});
    }
    // Bodies are in id order: equal depths go by id.
    std::stable_sort(order.begin(), order.end(),
                     [](const Candidate &a, const Candidate &b) { return a.depth < b.depth; });
    // Deleted in that order while each brings the deleted volume nearer the
    // goal; the rest grow.
    double deleted = 0;
    bool deleting = true;
    std::vector<std::size_t> growing;
    for (const Candidate &c : order) {
      const Body &seed = bodies_[c.i];
      double volume = ball_volume(seed.R);
      if (seed.twin >= 0) volume -= ball_volume(bodies_[static_cast<std::size_t>(seed.twin)].R);
      deleting = deleting && deleted + 0.5 * volume < goal;
      if (deleting) {
        deleted += volume;
        if (seed.twin < 0 && c.depth < 0) stats.displaced++;
        continue;
      }
      growing.push_back(c.i);
    }
    std::sort(growing.begin(), growing.end());
    std::vector<Vec3> first;
    for (std::size_t i : growing) first.push_back(out_of_bars(i));
    if (growing.empty() || grow_balance(growing, first, stats)) return records(stats);
    stats.displaced = displaced_before;    // the caller grows the block again
    jammed_ = true;
    return {};
  }

  // Where seed i starts its growth: where it was, pushed out of the bar
  // spheres it overlaps at kBalanceStart of its radius (a few passes, for
  // the beads of a chain); where it was if that leaves its cap or the walls
  // refuse it (the growth pushes it out then).
  Vec3 out_of_bars(std::size_t i) const
  {
    const Body &seed = bodies_[i];
    const double r = kBalanceStart * seed.R;
    Vec3 x = seed.x0;
    for (int pass = 0; pass < 3; ++pass)
      for (const Contact &c : contacts_[i]) {
        const Body &o = bodies_[static_cast<std::size_t>(c.j)];
        if (!o.rebar) continue;
        const double d = norm(x - o.x0);
        if (!(d < o.R + r)) continue;
        const Vec3 n =
            d > 1e-12 * o.R ? (1 / d) * (x - o.x0) : Vec3{seed.id < o.id ? -1.0 : 1.0, 0, 0};
        x = o.x0 + (o.R + r) * n;
      }
    if (norm(x - seed.x0) > seed.cap || !admissible(seed.x0, x, seed.R, domain_, settings_.tol))
      return seed.x0;
    return x;
  }

  // Where seed s may start: the points of a lattice (a quarter of its
  // radius apart) within its cap of where it was that overlap least, the
  // least first (then the nearest), admissible, at most kStarts, at least
  // a radius apart.
  std::vector<Vec3> starts(std::size_t s) const
  {
    const Body &seed = bodies_[s];
    const double h = kStartSpacing * seed.R;
    const int n = static_cast<int>(std::floor(seed.cap / h));
    // The present spheres a point within the cap can touch.
    std::vector<std::pair<Vec3, double>> near;
    for (const Contact &c : contacts_[s]) {
      const Body &o = bodies_[static_cast<std::size_t>(c.j)];
      if (o.present && norm(o.x - seed.x0) < seed.cap + seed.R + o.R) near.push_back({o.x, o.R});
    }
    // Each point reads one cell, which lists every sphere it can touch.
    double largest = 0;
    for (const auto &o : near) largest = std::max(largest, o.second);
    CellGrid grid(seed.R + largest);
    for (std::size_t k = 0; k < near.size(); ++k)
      grid.insert_around(near[k].first, static_cast<int>(k));
    const auto overlap_at = [&](Vec3 p) {
      double deepest = 0;
      grid.for_each_in_cell(p, [&](int k) {
        const auto &o = near[static_cast<std::size_t>(k)];
        deepest = std::max(deepest, seed.R + o.second - norm(p - o.first));
      });
      return deepest / seed.R;
    };
    std::vector<std::pair<double, Vec3>> scored;
    for (int i = -n; i <= n; ++i)
      for (int j = -n; j <= n; ++j)
        for (int k = -n; k <= n; ++k) {
          const Vec3 d{i * h, j * h, k * h};
          if (norm(d) > seed.cap) continue;
          const double o = overlap_at(seed.x0 + d);
          if (o <= kWorstStart) scored.push_back({o, seed.x0 + d});
        }
    // The least overlapped first, and of equal ones the nearest to where
    // it was: the smallest move that clears it.
    std::stable_sort(scored.begin(), scored.end(),
                     [&](const std::pair<double, Vec3> &a, const std::pair<double, Vec3> &b) {
                       if (a.first != b.first) return a.first < b.first;
                       return norm2(a.second - seed.x0) < norm2(b.second - seed.x0);
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

  // Body i moved along d as far as it goes, at most all of d: up to the
  // first present body it would touch (then tangent to it, exact but for
  // rounding), staying within its cap and admissible, else not at all; a
  // body that overlaps one where it is (the packing's own overlap) stays.
  // Returns the share of d moved; `normal` points from the body that
  // stopped it to where it stopped (zero when none did).
  double advance(std::size_t i, Vec3 d, Vec3 &normal)
  {
    Body &b = bodies_[i];
    normal = Vec3{};
    const double a = norm2(d);
    if (!(a > 0)) return 0;
    double t = 1;
    int stop = -1;
    for (const Contact &c : contacts_[i]) {
      const Body &o = bodies_[static_cast<std::size_t>(c.j)];
      if (!o.present) continue;
      // |rel + t d| = R (contact, less what the pair overlapped at the
      // start): the first root, for a pair that closes in.
      const Vec3 rel = b.x - o.x;
      const double R = b.R + o.R - c.allowed;
      if (R - norm(rel) > kClear * std::min(b.R, o.R)) return 0;
      const double half_b = dot(rel, d);
      if (!(half_b < 0)) continue;
      const double q = norm2(rel) - R * R;
      double at = 0;
      if (q > 0) {
        const double disc = half_b * half_b - a * q;
        if (disc < 0) continue;
        at = q / (-half_b + std::sqrt(disc));    // the smaller root, without cancellation
      }
      if (at < t) {
        t = at;
        stop = c.j;
      }
    }
    const Vec3 p = b.x + t * d;
    if (stop >= 0) {
      const Vec3 from = p - bodies_[static_cast<std::size_t>(stop)].x;
      const double n = norm(from);
      if (n > 0) normal = (1 / n) * from;
    }
    if (!(t > 0) || norm(p - b.x0) > b.cap || !admissible(b.x, p, b.R, domain_, settings_.tol))
      return 0;
    b.x = p;
    return t;
  }

  // The zone's matrix (the seeds out) settles onto the bars as hard
  // spheres: each, by id, steps towards its bar until it touches a sphere,
  // then slides along that sphere for the rest of the step, never into an
  // overlap; the steps shrink pass by pass. The room the targets left in caps against
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
        if (!(step > kSettleSmallest * b.R)) continue;
        const Vec3 d = (step / norm(to_bar)) * to_bar;
        Vec3 n;
        const double moved = advance(i, d, n);
        if (moved == 1 || norm2(n) == 0) continue;
        const Vec3 slide = d - dot(d, n) * n;
        if (norm(slide) > kSettleSmallest * b.R) advance(i, (step / norm(slide)) * slide, n);
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
    for (int k = 0; k < kAloneSweeps && !clear; ++k) clear = sweep(stats) <= kClear;
    seed.active = false;
    return clear && excess_of(s) == 0;
  }

  // Seed s goes to the first of its starts where it fits alone; else it
  // grows from the best ones in turn while the whole zone makes room; a
  // failed try leaves the zone as it was.
  void grow_seed(std::size_t s, RegrowthStats &stats)
  {
    Body &seed = bodies_[s];
    const std::vector<Vec3> places = starts(s);
    bool clear = false;
    for (std::size_t k = 0; k < places.size() && !clear; ++k)
      clear = fits_alone(s, places[k], stats);
    for (std::size_t k = 0; k < std::min(places.size(), kGrowthStarts) && !clear; ++k) {
      seed.x = places[k];
      clear = try_growth(s, stats);
    }
    if (!clear) seed.x = seed.x0;
    seed.present = clear;
    seed.placed = clear;
  }

  // The seeds of `waiting` all at once: each, by id, goes back where it
  // fits alone; the rest start at their least overlapped place, at
  // kStartScale of their radius, and grow together while the whole zone
  // relaxes. Whenever the zone jams (an overlap above kAbort after a growth
  // step, above kNearlyJammed after kJudgeIters steps once grown), the seed
  // that overlaps most is given up; then the zone relaxes to kClear, giving
  // up one more seed at each try that does not end clear. A shrunk seed's
  // shrunk sphere gives way while it tries, and comes back where the seed
  // is given up (or where it was, when the zone does not end clear).
  // Returns the shrunk seeds not put back, left for grow_seed: measured,
  // their own tries after the zone's put back a third more of them.
  std::vector<std::size_t> grow_together(const std::vector<std::size_t> &waiting,
                                         RegrowthStats &stats)
  {
    std::vector<std::size_t> growing;
    std::vector<Vec3> first;
    for (std::size_t i : waiting) {
      Body &seed = bodies_[i];
      const int twin = seed.twin;
      // A shrunk sphere that may not move (beyond the zone, an image) stays.
      if (twin >= 0 && !bodies_[static_cast<std::size_t>(twin)].movable) continue;
      show_twin(seed, false);
      seed.present = true;
      const std::vector<Vec3> places = starts(i);
      for (std::size_t k = 0; k < places.size() && !seed.placed; ++k)
        seed.placed = fits_alone(i, places[k], stats);
      seed.present = seed.placed;
      if (seed.placed) continue;
      seed.x = seed.x0;
      show_twin(seed, true);    // holds its place until the growth
      if (places.empty()) continue;
      growing.push_back(i);
      first.push_back(places.front());
    }
    if (!growing.empty()) grow_all(growing, first, stats);
    std::vector<std::size_t> shrunk;
    for (std::size_t i : waiting)
      if (bodies_[i].twin >= 0 && !bodies_[i].placed) shrunk.push_back(i);
    return shrunk;
  }

  // The seeds `growing` present at `first` at `start` of their radius (their
  // shrunk spheres out), and the zone's movable spheres made active.
  void start_growth(const std::vector<std::size_t> &growing, const std::vector<Vec3> &first,
                    double start)
  {
    for (std::size_t n = 0; n < growing.size(); ++n) {
      Body &seed = bodies_[growing[n]];
      show_twin(seed, false);
      seed.present = true;
      seed.x = first[n];
      seed.scale = start;
    }
    activate_zone();
  }

  // A growth ended: every sphere at its own radius, kept where it is when
  // `clear`; else the zone back where it was, the seeds `growing` given up
  // (their shrunk spheres back).
  void end_growth(const std::vector<std::size_t> &growing, bool clear)
  {
    for (std::size_t i : active_) bodies_[i].scale = 1;
    deactivate_zone(clear);
    for (std::size_t i : growing) {
      Body &seed = bodies_[i];
      seed.placed = seed.present = clear;
      seed.scale = 1;
      if (!clear) {
        seed.x = seed.x0;
        show_twin(seed, true);
      }
    }
  }

  // The seeds `growing` grown together from `first` (grow_together,
  // kTogether), the zone's matrix at its radii.
  void grow_all(std::vector<std::size_t> growing, const std::vector<Vec3> &first,
                RegrowthStats &stats)
  {
    const GrowthPlan &plan = kTogether;
    start_growth(growing, first, plan.start);
    double worst = 0;
    for (int step = 0; step <= plan.stages && !growing.empty(); ++step) {
      const double scale = plan.start + (1 - plan.start) * step / plan.stages;
      for (std::size_t i : growing) bodies_[i].scale = scale;
      worst = relax_.run(plan.stage_iters, kSettled, stats.sweeps);
      while (worst > kAbort && !growing.empty()) {
        give_up(most_overlapped(growing), growing);
        worst = relax_.run(plan.stage_iters, kSettled, stats.sweeps);
      }
    }
    for (;;) {
      worst = relax_.run(kJudgeIters, kClear, stats.sweeps);
      if (!(worst > kNearlyJammed) || growing.empty()) break;
      give_up(most_overlapped(growing), growing);
    }
    bool clear = false;
    for (;;) {
      worst = relax_.run(kRelaxIters, kClear, stats.sweeps);
      if (worst > kClear && worst < kNearlyJammed)
        worst = relax_.run(kRelaxMore, kClear, stats.sweeps);
      clear = finish_clear(worst, stats);
      if (clear || growing.empty()) break;
      give_up(most_overlapped(growing), growing);
    }
    end_growth(growing, clear);
  }

  // The seeds `growing` and the zone's matrix grown back together from
  // `first` (kBalance). What does not fit goes together, never a seed a
  // try (drop_until), and a zone that jams is seen at the stage that shows
  // it: a stage that leaves an overlap above kAbort gives up half of the
  // seeds above it, relaxes, and so on for at most kBalanceDrops rounds;
  // an overlap still above it, with no seed above it, is the matrix's own
  // (a dense scene) and the growth stops. Grown, the same above
  // kNearlyJammed, then the finish (finish_padded), the seeds still
  // overlapping given up half at a time before it runs again. A zone that
  // does not end clear goes back to where it was, its seeds given up (the
  // last resort; it returns whether the zone ended clear). A block's FIRE steps are bounded by the
  // stages and the rounds, whatever its count of seeds.
  bool grow_balance(std::vector<std::size_t> growing, const std::vector<Vec3> &first,
                    RegrowthStats &stats)
  {
    const GrowthPlan &plan = kBalance;
    start_growth(growing, first, plan.start);
    bool jammed = false;
    for (int step = 0; step <= plan.stages && !jammed; ++step) {
      const double scale = plan.start + (1 - plan.start) * step / plan.stages;
      const bool last = step == plan.stages;
      for (std::size_t i : active_) bodies_[i].scale = last ? 1.0 : scale;
      for (std::size_t i : growing) bodies_[i].scale = scale;
      if (scale < plan.pull_until) {
        relax_.set_pull(plan.pull);
        relax_.run(plan.pull_iters, -1, stats.sweeps);    // every step, overlaps or not
        relax_.set_pull(0);
      }
      double worst = relax_.run(plan.stage_iters, last ? kSettled : kBalanceSettled, stats.sweeps);
      worst = drop_until(growing, worst, kAbort, plan.stage_iters, stats);
      jammed = worst > kAbort;
    }
    bool clear = false;
    if (!jammed) {
      double worst = relax_.run(kJudgeIters, kNearlyJammed, stats.sweeps);
      worst = drop_until(growing, worst, kNearlyJammed, kJudgeIters, stats);
      clear = !(worst > kNearlyJammed) && finish_padded(stats);
      for (int k = 0; k < kBalanceDrops && !clear && worst <= kNearlyJammed; ++k)
        clear = drop_overlapped(growing, 0) && finish_padded(stats);
    }
    end_growth(growing, clear);
    return clear;
  }

  // While the zone's largest overlap `worst` exceeds `above`: half of the
  // growing seeds above it given up together (drop_overlapped), then at
  // most `iters` FIRE steps; at most kBalanceDrops rounds, and once no seed
  // is above it only one more relaxation (what is left is the matrix's).
  // Returns the largest overlap left.
  double drop_until(std::vector<std::size_t> &growing, double worst, double above, int iters,
                    RegrowthStats &stats)
  {
    bool longer = false;    // relaxed once more with no seed above it
    for (int k = 0; k < kBalanceDrops && worst > above; ++k) {
      if (!drop_overlapped(growing, above)) {
        if (longer) break;
        longer = true;
      }
      worst = relax_.run(iters, above, stats.sweeps);
    }
    return worst;
  }

  // Half of the growing seeds whose deepest overlap exceeds `above` (over
  // the smaller radius; at least one) given up together, the most
  // overlapped first, each only if it still exceeds it once those before it
  // are out. True when one was.
  bool drop_overlapped(std::vector<std::size_t> &growing, double above)
  {
    std::vector<std::pair<double, std::size_t>> order;
    for (std::size_t i : growing) {
      const double d = deepest(i);
      if (d > above) order.push_back({-d, i});
    }
    std::sort(order.begin(), order.end());    // the deepest first, equals by index
    order.resize((order.size() + 1) / 2);
    bool dropped = false;
    for (const auto &o : order)
      if (deepest(o.second) > above) {
        give_up(o.second, growing);
        dropped = true;
      }
    return dropped;
  }

  // The grown zone relaxed clear without the crawl to kClear: FIRE with the
  // contact distance of every pair of moving spheres padded by kPad of its
  // smaller radius until no padded overlap exceeds half of that (those
  // pairs then clear by half a pad), then at the true radii to kClear (the
  // pairs with a frozen sphere, unpadded: a few steps); checked by
  // finish_clear, which crawls on only from below kNearlyClear. True when
  // clear.
  bool finish_padded(RegrowthStats &stats)
  {
    relax_.set_pad(kPad);
    relax_.run(kRelaxIters, 0.5 * kPad, stats.sweeps);
    relax_.set_pad(0);
    return finish_clear(relax_.run(kRelaxIters, kClear, stats.sweeps), stats);
  }

  // The shrunk sphere of seed s (if any) present or not.
  void show_twin(const Body &seed, bool present)
  {
    if (seed.twin >= 0) bodies_[static_cast<std::size_t>(seed.twin)].present = present;
  }

  // The deepest overlap of body i at its radius now, over the smaller radius.
  double deepest(std::size_t i) const
  {
    const Body &b = bodies_[i];
    double most = 0;
    for (const Contact &c : contacts_[i]) {
      const Body &o = bodies_[static_cast<std::size_t>(c.j)];
      if (!o.present) continue;
      const double ri = radius(b), rj = radius(o);
      most = std::max(most, (ri + rj - norm(b.x - o.x)) / std::min(ri, rj));
    }
    return most;
  }

  // Of the growing seeds, the one that overlaps most (the first of equals).
  std::size_t most_overlapped(const std::vector<std::size_t> &growing) const
  {
    std::size_t pick = growing.front();
    double most = -INFINITY;
    for (std::size_t i : growing) {
      const double d = deepest(i);
      if (d > most) {
        most = d;
        pick = i;
      }
    }
    return pick;
  }

  // Growing seed s given up: it leaves the zone and the active spheres.
  void give_up(std::size_t s, std::vector<std::size_t> &growing)
  {
    const auto at = std::find(active_.begin(), active_.end(), s);
    if (at != active_.end()) {
      saved_.erase(saved_.begin() + (at - active_.begin()));
      active_.erase(at);
    }
    Body &seed = bodies_[s];
    seed.active = seed.present = false;
    seed.scale = 1;
    seed.x = seed.x0;
    growing.erase(std::find(growing.begin(), growing.end(), s));
    if (seed.twin < 0) return;
    // Its shrunk sphere comes back where it was and moves on with the zone
    // (kept in the active spheres' id order).
    const std::size_t t = static_cast<std::size_t>(seed.twin);
    Body &shrunk = bodies_[t];
    const auto to = std::lower_bound(active_.begin(), active_.end(), t);
    saved_.insert(saved_.begin() + (to - active_.begin()), shrunk.x);
    active_.insert(to, t);
    shrunk.present = shrunk.active = true;
    shrunk.w = 1;
  }

  // The zone's present movable spheres made active (in id order), their
  // places saved.
  void activate_zone()
  {
    active_.clear();
    saved_.clear();
    for (std::size_t i = 0; i < bodies_.size(); ++i) {
      Body &b = bodies_[i];
      if (!b.movable || !b.present) continue;
      b.active = true;
      b.w = 1;
      active_.push_back(i);
      saved_.push_back(b.x);
    }
  }

  // The active spheres made inactive, back where they were unless `keep`.
  void deactivate_zone(bool keep)
  {
    for (std::size_t n = 0; n < active_.size(); ++n) {
      Body &b = bodies_[active_[n]];
      b.active = false;
      if (!keep) b.x = saved_[n];
    }
    active_.clear();
  }

  // True when no active sphere overlaps anything (by more than kClear),
  // after FIRE left overlaps of at most `worst`: at once when that is
  // below kClear, else, when they are below kNearlyClear, by more FIRE
  // steps, then projection sweeps.
  bool finish_clear(double worst, RegrowthStats &stats)
  {
    bool clear = false;
    if (worst <= kClear) {
      clear = true;
    } else if (worst <= kNearlyClear) {
      clear = relax_.run(kFinishIters, kClear, stats.sweeps) <= kClear;
      for (int k = 0; k < kFinalSweeps && !clear; ++k) clear = sweep(stats) <= kClear;
    }
    for (std::size_t i : active_)
      if (clear && excess_of(i) > 0) clear = false;
    return clear;
  }

  // Seed s grows from where it is while every movable sphere of the zone
  // relaxes; true when the zone ends clear, else it goes back.
  bool try_growth(std::size_t s, RegrowthStats &stats)
  {
    Body &seed = bodies_[s];
    activate_zone();
    double worst = 0;
    for (int step = 0; step <= kGrowthSteps && worst <= kAbort; ++step) {
      seed.scale = kStartScale + (1 - kStartScale) * step / kGrowthSteps;
      worst = relax_.run(kStepIters, kSettled, stats.sweeps);
    }
    if (worst <= kAbort) worst = relax_.run(kRelaxIters, kClear, stats.sweeps);
    seed.scale = 1;
    const bool clear = worst <= kAbort && finish_clear(worst, stats);
    deactivate_zone(clear);
    return clear;
  }

  // The zone's matrix (the seeds out) pulled towards the bars as soft
  // spheres, then relaxed: kept when it ends clear, else tried again with
  // a weaker pull, or left as it was.
  void compact(RegrowthStats &stats)
  {
    activate_zone();
    const std::vector<Vec3> before = saved_;
    bool clear = false;
    double pull = kPull;
    for (int k = 0; k < kCompactTries && !clear; ++k, pull *= kPullDecay) {
      for (std::size_t n = 0; n < active_.size(); ++n) bodies_[active_[n]].x = before[n];
      relax_.set_pull(pull);
      relax_.run(kCompactIters, 0, stats.sweeps);
      relax_.set_pull(0);
      double worst = relax_.run(kRelaxIters, kClear, stats.sweeps);
      if (worst > kClear && worst < kNearlyJammed)
        worst = relax_.run(kRelaxMore, kClear, stats.sweeps);
      clear = finish_clear(worst, stats);
    }
    deactivate_zone(clear);
  }

  // A seed whose centre lies inside a bar sphere is what the bar displaces:
  // deleted before the growth.
  void delete_displaced(RegrowthStats &stats)
  {
    for (std::size_t i = 0; i < bodies_.size(); ++i) {
      Body &b = bodies_[i];
      if (!b.seed || b.twin >= 0) continue;    // a shrunk one is placed already
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

  // One Gauss-Seidel sweep over the active spheres: each, by id, moves out
  // of its overlaps (its share of each against an active sphere, by
  // mobility; all of it against any other), by tol of the smaller radius
  // more, then back
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
        const double excess = ri + rj - dist - c.allowed;
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

  // The overlaps of body i above kClear (and above what is allowed), summed,
  // over the smaller radius of each pair.
  double excess_of(std::size_t i) const
  {
    const Body &b = bodies_[i];
    double sum = 0;
    for (const Contact &c : contacts_[i]) {
      const Body &o = bodies_[static_cast<std::size_t>(c.j)];
      if (!o.present) continue;
      const double small = std::min(b.R, o.R);
      const double excess = (b.R + o.R - norm(b.x - o.x) - c.allowed) / small;
      if (excess > kClear) sum += excess;
    }
    return sum;
  }

  std::vector<RoundRecord> records(RegrowthStats &stats) const
  {
    std::vector<RoundRecord> out;
    for (std::size_t i = 0; i < bodies_.size(); ++i) {
      const Body &b = bodies_[i];
      if (!b.movable) continue;
      const bool twin_placed = b.twin >= 0 && bodies_[static_cast<std::size_t>(b.twin)].placed;
      if (!b.seed && twin_placed) continue;    // its seed's record moves the atom
      if (b.seed && b.twin >= 0) {
        stats.shrunk_seeds++;
        if (!b.placed) continue;    // it stays shrunk where it was placed
        stats.shrunk_regrown++;
        const double r = bodies_[static_cast<std::size_t>(b.twin)].R;
        stats.volume_regrown += 4.0 / 3.0 * M_PI * (b.R * b.R * b.R - r * r * r);
        out.push_back({b.id, RecordKind::Placed, b.x, b.R});
      } else if (!b.present) {    // only a seed leaves: no matrix sphere is deleted
        stats.deleted++;
        stats.seeds++;
        out.push_back({b.id, RecordKind::Deleted, b.x0, b.R});
        continue;
      } else if (b.seed) {
        stats.seeds++;
        stats.regrown++;
        stats.volume_regrown += 4.0 / 3.0 * M_PI * b.R * b.R * b.R;
        out.push_back({b.id, RecordKind::Placed, b.x, b.R});
      } else {
        const Vec3 dx = b.x - b.x0;
        if (norm2(dx) == 0) continue;
        stats.moved++;
        stats.max_move = std::max(stats.max_move, norm(dx) / settings_.rmin);
        // Where it ends, not how far it went: a process that sees the atom
        // only as a periodic image gets the same copies as its owner.
        out.push_back({b.id, RecordKind::Moved, wrapped_into_box(b.x, domain_), 0});
      }
      // At their own radii, against everything present, beyond what each
      // pair overlapped at the start.
      double largest = 0;
      bool exact = true;
      for (const Contact &c : contacts_[i]) {
        const Body &o = bodies_[static_cast<std::size_t>(c.j)];
        if (!o.present) continue;
        const double overlap = b.R + o.R - norm(b.x - o.x) - c.allowed;
        largest = std::max(largest, overlap / settings_.rmin);
        exact = exact && !(overlap > kRegrowthExact * std::min(b.R, o.R));
      }
      stats.max_overlap = std::max(stats.max_overlap, largest);
      if (!exact) stats.inexact++;
    }
    return out;
  }

  const Settings &settings_;
  bool jammed_ = false;
  const Domain &domain_;
  double width_;
  std::vector<Body> bodies_;
  std::vector<std::vector<Contact>> contacts_;
  std::vector<std::size_t> active_;    // the spheres that move now (by id)
  std::vector<Vec3> saved_;            // where they were before it
  SoftRelaxation relax_{bodies_, active_, domain_, settings_.tol};
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
  std::vector<RoundRecord> out = zone.run(stats);
  if (!zone.jammed()) return out;
  // The rebuilt zone jammed (a dense or settled packing): the block's
  // targets without a place grown back as grow together does, in the same
  // zone (in a zone of 5 rmax, grow together's, the LIGGGHTS example kept
  // 10 of its 93 where this keeps 27); those placed shrunk stay shrunk.
  Settings together = settings;
  together.grow_balance = false;
  together.grow_together = true;
  Zone fallback(reads, seeds, width, together, domain);
  fallback.leave_shrunk();
  return fallback.run(stats);
}

}    // namespace reinforce
