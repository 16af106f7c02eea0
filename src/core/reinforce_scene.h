// The scene of one relocation call: what a process sees while it
// relocates, with the spheres it places and pushes (docs/design.md, "The
// relocation engine").
#pragma once

#include "reinforce_ball_sample.h"
#include "reinforce_candidate_order.h"
#include "reinforce_cell_grid.h"
#include "reinforce_particle.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>
#include <vector>

namespace reinforce {

// The spheres a process sees while it relocates: the particles, then the
// relocated spheres and their periodic images as they are added. Present
// spheres can be pushed; every copy of an atom moves with it.
class Scene {
public:
  Scene(const std::vector<Particle> &particles, double cell, double zone)
      : grid_(cell), largest_r_(0)
  {
    for (const Particle &p : particles) largest_r_ = std::max(largest_r_, p.r);
    for (const Particle &p : particles)
      add(p.x, p.r, p.id, p.role != Role::Target, p.role == Role::Matrix && p.pushable,
          p.role == Role::Rebar);
    // Only matrix spheres within `zone` of a bar may be pushed (none with
    // a negative zone: size fit pushes nothing).
    for (std::size_t i = 0; i < x_.size(); ++i)
      if (pushable_[i]) pushable_[i] = zone >= 0 && gap_to_rebar(x_[i], r_[i], zone) <= zone;
  }

  int add(Vec3 x, double r, std::int64_t id, bool present, bool pushable, bool rebar = false)
  {
    const int index = static_cast<int>(x_.size());
    x_.push_back(x);
    r_.push_back(r);
    id_.push_back(id);
    present_.push_back(present);
    pushable_.push_back(pushable);
    rebar_.push_back(rebar);
    grid_.insert(x, index);
    if (present && copies_built_) copies_[id].push_back(index);
    largest_r_ = std::max(largest_r_, r);
    return index;
  }

  // Takes a sphere out of the view (a failed attempt's new sphere).
  void remove(int j)
  {
    grid_.erase(x_[j], j);
    build_copies();
    present_[j] = false;
    std::vector<int> &c = copies_[id_[j]];
    c.erase(std::remove(c.begin(), c.end(), j), c.end());
  }

  void set_present(int j, bool pushable)
  {
    build_copies();
    present_[j] = true;
    pushable_[j] = pushable;
    copies_[id_[j]].push_back(j);
  }

  // Moves every present copy of sphere j's atom by dx.
  void shift(int j, Vec3 dx)
  {
    build_copies();
    for (int c : copies_[id_[j]]) place(c, x_[c] + dx);
  }
  void place(int j, Vec3 x)
  {
    grid_.move(x_[j], x, j);
    x_[j] = x;
  }

  // Smallest surface gap from sphere (x, r) to a rebar sphere, searched out
  // to `range` (beyond it: +infinity).
  double gap_to_rebar(Vec3 x, double r, double range) const
  {
    double best = INFINITY;
    grid_.for_each_near(x, r + range + largest_r_, [&](int b) {
      if (rebar_[b]) best = std::min(best, norm(x_[b] - x) - r_[b] - r);
    });
    return best;
  }

  // Volume fraction of sphere (x, r) inside the union of the rebar spheres.
  double fraction_in_rebar(Vec3 x, double r) const
  {
    std::vector<int> bars;
    grid_.for_each_near(x, r + largest_r_, [&](int b) {
      if (rebar_[b] && norm(x_[b] - x) < r + r_[b]) bars.push_back(b);
    });
    if (bars.empty()) return 0;
    return ball_fraction(x, r, [&](Vec3 p) {
      for (int b : bars)
        if (norm2(p - x_[b]) < r_[b] * r_[b]) return true;
      return false;
    });
  }

  // True when sphere (c, r) overlaps no present sphere by more than
  // tol * min of the two radii; `deepest` gets its largest overlap (length).
  bool fits(Vec3 c, double r, double tol, double &deepest, int skip_id = -1) const
  {
    bool ok = true;
    deepest = 0;
    grid_.for_each_near(c, r + largest_r_, [&](int j) {
      if (!ok || !present_[j] || id_[j] == skip_id) return;
      const double overlap = r + r_[j] - norm(c - x_[j]);
      deepest = std::max(deepest, overlap);
      ok = overlap <= tol * std::min(r, r_[j]);
    });
    return ok;
  }

  // Largest overlap (length) of sphere j with a present sphere of another
  // atom; with matrix_only, rebar spheres are left out.
  double deepest_overlap(int j, bool matrix_only = false) const
  {
    double deepest = 0;
    grid_.for_each_near(x_[j], r_[j] + largest_r_, [&](int k) {
      if (!present_[k] || id_[k] == id_[j] || (matrix_only && rebar_[k])) return;
      deepest = std::max(deepest, r_[j] + r_[k] - norm(x_[j] - x_[k]));
    });
    return deepest;
  }

  // Present spheres whose surface gap to sphere (x, r) is at most `search`,
  // nearest first, with at most `max_rebar` rebar spheres (the nearest): at
  // least the `wanted` nearest (all of them when fewer lie within
  // `search`). The query grows until it holds them, so its cost follows the
  // spheres found, not the gap asked. A thin bar is a chain of many small
  // spheres: left alone they would fill the list, and four beads of one
  // chain share only tangent spheres of their own size.
  std::vector<Candidate> candidates(Vec3 x, double r, double search, std::size_t wanted,
                                    int max_rebar) const
  {
    double range = r + 2 * largest_r_;
    for (;;) {
      const double complete = std::min(search, range - r - largest_r_);
      std::vector<Candidate> out;
      grid_.for_each_near(x, range, [&](int j) {
        if (!present_[j]) return;
        const double gap = norm(x_[j] - x) - r_[j] - r;
        if (gap <= complete) out.push_back({gap, id_[j], j});
      });
      std::sort(out.begin(), out.end());
      int rebar = 0;
      out.erase(std::remove_if(
                    out.begin(), out.end(),
                    [&](const Candidate &c) { return rebar_[c.index] && ++rebar > max_rebar; }),
                out.end());
      // Every view that holds the spheres within `complete` gives the same
      // list up to here: the answer does not depend on the process count.
      if (out.size() >= wanted || complete >= search) return out;
      range *= 2;
    }
  }

  // Present spheres overlapping sphere j by more than `limit` of the
  // smaller radius, in the same order on every process.
  std::vector<int> overlapping(int j, double limit) const
  {
    std::vector<int> out;
    grid_.for_each_near(x_[j], r_[j] + largest_r_, [&](int k) {
      if (k == j || !present_[k] || id_[k] == id_[j]) return;
      if (r_[j] + r_[k] - norm(x_[j] - x_[k]) > limit * std::min(r_[j], r_[k])) out.push_back(k);
    });
    std::sort(out.begin(), out.end(),
              [&](int a, int b) { return same_order_everywhere(id_[a], x_[a], id_[b], x_[b]); });
    return out;
  }

  Sphere sphere(int j) const { return {x_[j], r_[j]}; }
  Vec3 x(int j) const { return x_[j]; }
  double r(int j) const { return r_[j]; }
  std::int64_t id(int j) const { return id_[j]; }
  bool pushable(int j) const { return pushable_[j]; }
  const std::vector<int> &copies(std::int64_t id)
  {
    build_copies();
    return copies_[id];
  }

private:
  CellGrid grid_;
  double largest_r_;
  std::vector<Vec3> x_;
  std::vector<double> r_;
  std::vector<std::int64_t> id_;
  std::vector<bool> present_, pushable_, rebar_;
  // Present copies by id, built on first use: only pushing and kept targets
  // need them, and building them for every sphere of every round costs more
  // than the relocation of a small round.
  std::unordered_map<std::int64_t, std::vector<int>> copies_;
  bool copies_built_ = false;
  void build_copies()
  {
    if (copies_built_) return;
    copies_built_ = true;
    for (std::size_t i = 0; i < x_.size(); ++i)
      if (present_[i]) copies_[id_[i]].push_back(static_cast<int>(i));
  }
};

}    // namespace reinforce
