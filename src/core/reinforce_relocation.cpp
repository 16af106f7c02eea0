// The relocation of the targets of one round: the driver that takes each
// target in turn through the void search, making room and the seed paper's
// placement, and what it reports (docs/design.md, "The relocation engine").
#include "reinforce_relocation.h"

#include "reinforce_cell_grid.h"
#include "reinforce_rearrangement.h"
#include "reinforce_scene.h"
#include "reinforce_void_search.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <unordered_map>

namespace reinforce {

namespace {

// One target's relocation, given the scene and the settings.
class Relocator {
public:
  Relocator(Scene &scene, const Settings &s, const Domain &domain, Stats &stats)
      : scene_(scene), s_(s), domain_(domain), voids_(scene, s, domain, stats),
        room_(scene, s, domain, stats)
  {
  }

  // Spheres placed or moved so far (indices; repeats allowed).
  std::vector<int> touched;

  // Places the target at index t, or returns -1. On success the index of the
  // new sphere's primary copy.
  int relocate(int t, std::map<std::int64_t, Vec3> &pushes)
  {
    const Vec3 x0 = scene_.x(t);
    const double r0 = scene_.r(t);
    const std::int64_t id = scene_.id(t);
    if (s_.size == SizeMode::Keep) {
      // Its own radius, in a void that holds it as it is;
      Void own;
      if (voids_.own_size_void(x0, r0, own)) return commit(scene_.add(own.c, r0, id, true, true));
      // with `push`, where room can be made: first its own place, pushed
      // out of the bars, its neighbours pushed on (it was part of the
      // packing, so that disturbs least), then the voids the inversion
      // finds nearby;
      if (s_.push > 0) {
        const int in_place = room_.make_room(x0, x0, r0, id, pushes, touched);
        if (in_place >= 0) return commit(in_place);
        for (const Void &v : voids_.find_voids(x0, r0)) {
          const int fresh = room_.make_room(v.c, x0, r0, id, pushes, touched);
          if (fresh >= 0) return commit(fresh);
        }
      }
    }
    // else the seed paper's placement, in the void it fits.
    Void v;
    if (!voids_.best_fit(x0, r0, v)) return -1;
    return commit(scene_.add(v.c, v.r, id, true, true));
  }

private:
  Scene &scene_;
  const Settings &s_;
  const Domain &domain_;
  VoidSearch voids_;
  Rearrangement room_;

  // The new sphere is present for the targets after it, with its periodic
  // images inside this view (the host would make ghosts of them).
  int commit(int fresh)
  {
    const Vec3 c = scene_.x(fresh);
    const double r = scene_.r(fresh);
    touched.push_back(fresh);
    for (const Vec3 &image : images_in_view(c, domain_, false))
      touched.push_back(scene_.add(image, r, scene_.id(fresh), true, true));
    return fresh;
  }
};

}    // namespace

Footprint footprint(const Settings &s, double target_rmax, double largest_r)
{
  Footprint f;
  // A new centre stays within target_r + search of the old one.
  const double placed = target_rmax + s.search;
  if (s.size == SizeMode::Fit || !(s.push > 0)) {
    f.write = placed;
    f.read = placed + s.rmax + largest_r;
    return f;
  }
  // Pushed spheres start within target_r + 2 rmax of the new centre and
  // move at most `push`; whether one may move depends on the bars within
  // `zone` of it.
  f.write = placed + target_rmax + 2 * s.rmax + s.push;
  f.read = f.write + std::max(s.rmax + largest_r, s.zone + s.rmax + largest_r);
  return f;
}

namespace {

// The particles that can matter to the targets picked by `mine`: those
// whose centre lies within the footprint's read reach of one of them (the
// host's view is usually much larger). `index` maps back to `particles`.
std::vector<Particle> near_targets(const std::vector<Particle> &particles, const Settings &settings,
                                   const std::function<bool(const Particle &)> &mine,
                                   std::vector<std::size_t> &index)
{
  std::vector<std::size_t> targets;
  double target_rmax = 0, largest_r = settings.rmax;
  for (std::size_t i = 0; i < particles.size(); ++i) {
    const Particle &p = particles[i];
    largest_r = std::max(largest_r, p.r);
    if (p.role == Role::Target && (mine ? mine(p) : p.owned)) {
      targets.push_back(i);
      target_rmax = std::max(target_rmax, p.r);
    }
  }
  std::vector<Particle> out;
  index.clear();
  if (targets.empty()) return out;
  const double read = footprint(settings, target_rmax, largest_r).read;
  // Each target listed in the cells around its own (cells `read` wide): a
  // particle within `read` of it finds it in its one cell. One lookup per
  // particle, as this runs every round over the whole view.
  CellGrid grid(read * (1 + 1e-9));    // a hair wider: rounding of floor()
  for (std::size_t t : targets) grid.insert_around(particles[t].x, static_cast<int>(t));
  for (std::size_t i = 0; i < particles.size(); ++i) {
    bool near = false;
    grid.for_each_in_cell(particles[i].x, [&](int t) {
      near = near || norm(particles[t].x - particles[i].x) <= read;
    });
    if (!near) continue;
    index.push_back(i);
    out.push_back(particles[i]);
  }
  return out;
}

}    // namespace

Relocation relocate_targets(const std::vector<Particle> &all, const Settings &settings,
                            const Domain &domain, bool keep_unplaced, Stats &stats,
                            const std::function<bool(const Particle &)> &mine)
{
  std::vector<std::size_t> index;
  const std::vector<Particle> particles = near_targets(all, settings, mine, index);
  Relocation out;
  std::vector<std::size_t> targets;
  std::unordered_map<std::int64_t, std::vector<int>> vacant;    // target copies by id
  double largest_r = settings.rmax;
  for (std::size_t i = 0; i < particles.size(); ++i) {
    const Particle &p = particles[i];
    largest_r = std::max(largest_r, p.r);
    if (p.role != Role::Target) continue;
    vacant[p.id].push_back(static_cast<int>(i));
    if (mine ? mine(p) : p.owned) targets.push_back(i);
  }
  if (targets.empty()) return out;
  // size keep: largest first, so that the voids that hold a sphere as it is
  // go to the spheres that need them most (a smaller one may still find a
  // void of its own size after). The order among the targets of one block
  // of the schedule is the same whichever process relocates it.
  const bool largest_first = settings.size == SizeMode::Keep;
  std::sort(targets.begin(), targets.end(), [&](std::size_t a, std::size_t b) {
    if (largest_first && particles[a].r != particles[b].r) return particles[a].r > particles[b].r;
    return same_order_everywhere(particles[a].id, particles[a].x, particles[b].id, particles[b].x);
  });

  Scene scene(particles, 2 * largest_r,
              settings.size == SizeMode::Keep && settings.push > 0 ? settings.zone : -1);
  Relocator relocator(scene, settings, domain, stats);
  std::map<std::int64_t, Vec3> pushes;
  std::vector<int> placed_at;    // the new sphere's index, per placed result
  for (std::size_t t : targets) {
    const Particle &target = particles[t];
    stats.targets++;
    stats.volume_before += ball_volume(target.r);
    TargetResult result;
    result.index = t;
    result.id = target.id;
    int fresh = -1;
    if (settings.displaced <= 1 &&
        scene.fraction_in_rebar(target.x, target.r) >= settings.displaced) {
      result.outcome = Outcome::Displaced;
      stats.displaced++;
    } else {
      fresh = relocator.relocate(static_cast<int>(t), pushes);
      result.outcome = fresh >= 0 ? Outcome::Placed : Outcome::Unplaced;
    }
    if (result.outcome == Outcome::Placed) {
      stats.relocated++;
      stats.volume_after += ball_volume(scene.r(fresh));
      if (scene.r(fresh) < target.r * (1 - settings.tol)) {
        stats.shrunk++;
        // The regrowth takes up every target placed shrunk.
        if (settings.regrow > 0) out.placed_shrunk.push_back({target.id, target.x, target.r});
      }
    } else {
      stats.unplaced++;
      // Why, for the log: no group of four spheres to be tangent to at all.
      if (result.outcome == Outcome::Unplaced &&
          scene.candidates(target.x, target.r, settings.search, 4, kMaxRebarCandidates).size() < 4)
        stats.isolated++;
      if (keep_unplaced && result.outcome == Outcome::Unplaced) {
        // Present from now on, never pushed; what it overlaps is reported.
        for (int copy : vacant[target.id]) scene.set_present(copy, false);
        stats.max_kept_overlap =
            std::max(stats.max_kept_overlap,
                     scene.deepest_overlap(static_cast<int>(t), true) / settings.rmin);
      } else {
        stats.volume_removed += ball_volume(target.r);
      }
    }
    out.targets.push_back(result);
    placed_at.push_back(fresh);
  }
  // The largest overlap left by what was placed or moved, after every push.
  for (int j : relocator.touched) {
    stats.max_overlap = std::max(stats.max_overlap, scene.deepest_overlap(j) / settings.rmin);
  }
  // Final places: a relocated sphere may have been pushed by later ones.
  for (std::size_t k = 0; k < out.targets.size(); ++k) {
    if (placed_at[k] < 0) continue;
    out.targets[k].x = scene.x(placed_at[k]);
    out.targets[k].r = scene.r(placed_at[k]);
    pushes.erase(out.targets[k].id);
  }
  for (TargetResult &t : out.targets) t.index = index[t.index];
  for (const auto &[id, dx] : pushes) {
    out.pushes.push_back({id, dx});
    stats.max_push = std::max(stats.max_push, norm(dx) / settings.rmin);
  }
  return out;
}

}    // namespace reinforce
