#include "reinforce_regrowth_zone.h"

#include "reinforce_cell_grid.h"
#include "reinforce_regrowth.h"

#include <algorithm>
#include <cmath>
#include <tuple>
#include <unordered_map>

namespace reinforce {

std::vector<Body> zone_bodies(const std::vector<Particle> &reads,
                              const std::vector<std::size_t> &seeds, double width)
{
  std::vector<Body> bodies;
  std::vector<std::size_t> seed_list(seeds);
  std::sort(seed_list.begin(), seed_list.end(),
            [&](std::size_t a, std::size_t b) { return reads[a].id < reads[b].id; });
  // Only the nearest seed within the width matters (cells of that size).
  CellGrid near_seed(width);
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
    b.movable = p.role == Role::Matrix && p.pushable && !p.other_rebar && nearest < width;
    if (b.movable) {
      b.w_zone = 1 - nearest / width;
      b.cap = regrowth_policy::kMoveShare * width * b.w_zone;
      copies[b.id]++;
    }
    bodies.push_back(b);
  }
  // An atom seen twice here (periodic images) stays where it is: moving
  // one copy would leave the other behind.
  for (Body &b : bodies)
    if (b.movable && copies[b.id] > 1) b.movable = false;
  for (std::size_t s : seed_list) {
    Body b;
    b.x = b.x0 = reads[s].x;
    b.R = reads[s].r;
    b.id = reads[s].id;
    b.seed = b.movable = true;
    b.cap = regrowth_policy::kMoveShare * width;
    bodies.push_back(b);
  }
  // Sweeps go by id (then place: frozen images share one), whatever the
  // order of `reads`.
  std::sort(bodies.begin(), bodies.end(), [](const Body &a, const Body &b) {
    return std::tie(a.id, a.x0.x, a.x0.y, a.x0.z) < std::tie(b.id, b.x0.x, b.x0.y, b.x0.z);
  });
  std::vector<int> bars;
  for (std::size_t k = 0; k < bodies.size(); ++k)
    if (bodies[k].rebar) bars.push_back(static_cast<int>(k));
  // Twins: one id, sorted next to each other.
  for (std::size_t k = 0; k < bodies.size(); ++k) {
    if (!bodies[k].seed) continue;
    for (std::size_t j = k; j-- > 0 && bodies[j].id == bodies[k].id;)
      if (!bodies[j].seed) bodies[k].twin = static_cast<int>(j);
    for (std::size_t j = k + 1; j < bodies.size() && bodies[j].id == bodies[k].id; ++j)
      if (!bodies[j].seed) bodies[k].twin = static_cast<int>(j);
    if (bodies[k].twin >= 0)
      bodies[static_cast<std::size_t>(bodies[k].twin)].twin = static_cast<int>(k);
  }
  for (Body &b : bodies) {
    if (!b.movable || b.seed) continue;
    double nearest = INFINITY;
    for (int k : bars) {
      const Body &bar = bodies[static_cast<std::size_t>(k)];
      const double gap = norm(b.x0 - bar.x0) - bar.R;
      if (gap < nearest) {
        nearest = gap;
        b.bar = k;
      }
    }
  }
  return bodies;
}

std::vector<std::vector<Contact>> zone_contacts(const std::vector<Body> &bodies)
{
  std::vector<std::vector<Contact>> contacts;
  double largest = 0, cap = 0;
  for (const Body &b : bodies) {
    largest = std::max(largest, b.R);
    cap = std::max(cap, b.cap);
  }
  CellGrid grid(2 * (largest + cap));
  for (std::size_t k = 0; k < bodies.size(); ++k) grid.insert(bodies[k].x0, static_cast<int>(k));
  contacts.assign(bodies.size(), {});
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    const Body &b = bodies[i];
    if (!b.movable) continue;
    grid.for_each_near(b.x0, b.R + largest + b.cap + cap, [&](int j) {
      if (static_cast<std::size_t>(j) == i) return;
      const Body &o = bodies[static_cast<std::size_t>(j)];
      // Neither can come closer than this: caps bound their moves.
      if (!can_touch(b, o)) return;
      contacts[i].push_back({j, allowed_overlap(b, o)});
    });
    std::sort(contacts[i].begin(), contacts[i].end(),
              [](const Contact &a, const Contact &c) { return a.j < c.j; });
  }
  return contacts;
}

}    // namespace reinforce
