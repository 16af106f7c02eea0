// Engine tests on synthetic scenes: a jittered polydisperse packing with a
// bar of overlapping spheres through it, seen by one process.
#include "reinforce_cell_grid.h"
#include "reinforce_packing_scan.h"
#include "reinforce_relocation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>

using namespace reinforce;

namespace {

constexpr double kRmin = 0.02, kRmax = 0.04;

struct Scene {
  std::vector<Particle> particles;
  Domain domain;
};

// Matrix spheres on a jittered cubic lattice (no overlaps), radii uniform in
// [kRmin, kRmax], in the box [0,1]x[0,0.5]x[0,0.5]; one bar along x at
// (y, z) = (0.25, 0.25) made of spheres of radius bar_r every 0.8 * 2 bar_r.
Scene make_scene(unsigned seed, double bar_r = 0.03, double spacing = 0.085)
{
  Scene s;
  s.domain.lo = {0, 0, 0};
  s.domain.hi = {1, 0.5, 0.5};
  s.domain.view_lo = {-1, -1, -1};
  s.domain.view_hi = {2, 2, 2};
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unif(0, 1);
  std::int64_t id = 1;
  // Whole cells per box length, so the lattice is also periodic.
  int cells[3];
  Vec3 step;
  for (int d = 0; d < 3; ++d) {
    cells[d] = static_cast<int>((s.domain.hi[d] - s.domain.lo[d]) / spacing);
    step[d] = (s.domain.hi[d] - s.domain.lo[d]) / cells[d];
  }
  for (int i = 0; i < cells[0]; ++i)
    for (int j = 0; j < cells[1]; ++j)
      for (int k = 0; k < cells[2]; ++k) {
        const double r = kRmin + (kRmax - kRmin) * unif(rng);
        Vec3 c;
        const int ijk[3] = {i, j, k};
        for (int d = 0; d < 3; ++d)
          c[d] = (ijk[d] + 0.5) * step[d] + (step[d] / 2 - r) * (2 * unif(rng) - 1);
        s.particles.push_back({c, r, id++, Role::Matrix, true});
      }
  for (double x = bar_r; x <= 1 - bar_r; x += 1.6 * bar_r)
    s.particles.push_back({{x, 0.25, 0.25}, bar_r, id++, Role::Rebar, true});
  return s;
}

Settings default_settings(SizeMode size = SizeMode::Keep)
{
  Settings st;
  st.rmin = kRmin;
  st.rmax = kRmax;
  st.search = 2 * kRmax;
  st.zone = 3 * kRmax;
  st.push = kRmax;
  st.size = size;
  return st;
}

void mark(Scene &s, double tol)
{
  for (std::size_t i : find_targets(s.particles, tol)) s.particles[i].role = Role::Target;
}

// The scene after a relocation: relocated spheres moved, pushed ones
// shifted (every copy), unplaced ones deleted (or kept).
std::vector<Particle> apply(const Scene &s, const Relocation &rel, bool keep)
{
  std::vector<Particle> out = s.particles;
  std::vector<bool> gone(out.size(), false);
  for (const TargetResult &t : rel.targets) {
    if (t.outcome == Outcome::Placed) {
      out[t.index].x = t.x;
      out[t.index].r = t.r;
      out[t.index].role = Role::Matrix;
    } else if (keep) {
      out[t.index].role = Role::Matrix;
    } else {
      gone[t.index] = true;
    }
  }
  for (const Push &p : rel.pushes)
    for (Particle &q : out)
      if (q.id == p.id) q.x = q.x + p.dx;
  std::vector<Particle> kept;
  for (std::size_t i = 0; i < out.size(); ++i)
    if (!gone[i]) kept.push_back(out[i]);
  return kept;
}

// Largest overlap, relative to min radius, of a moved sphere with any other
// sphere (brute force: the reference the engine's grid is checked against).
double worst_overlap_of_moved(const std::vector<Particle> &after, const Scene &before)
{
  double worst = -INFINITY;
  for (std::size_t i = 0; i < after.size(); ++i) {
    const Particle &p = after[i];
    bool moved = true;
    for (const Particle &q : before.particles)
      if (q.id == p.id) moved = q.x.x != p.x.x || q.x.y != p.x.y || q.x.z != p.x.z || q.r != p.r;
    if (!moved) continue;
    for (std::size_t j = 0; j < after.size(); ++j) {
      if (j == i) continue;
      const Particle &q = after[j];
      worst = std::max(worst, (p.r + q.r - norm(p.x - q.x)) / std::min(p.r, q.r));
    }
  }
  return worst;
}

// The targets of s marked and relocated with size keep, no pushing, every
// target tried; `st` gets the settings.
Relocation relocate_keep_without_push(Scene &s, Settings &st, Stats &stats)
{
  st = default_settings();
  st.push = 0;
  st.displaced = 2;
  mark(s, st.tol);
  return relocate_targets(s.particles, st, s.domain, false, stats);
}

// The same targets, outcomes, places, radii and pushes, bit for bit.
void expect_same_relocation(const Relocation &a, const Relocation &b)
{
  ASSERT_EQ(a.targets.size(), b.targets.size());
  for (std::size_t i = 0; i < a.targets.size(); ++i) {
    EXPECT_EQ(a.targets[i].id, b.targets[i].id);
    EXPECT_EQ(a.targets[i].outcome, b.targets[i].outcome);
    EXPECT_EQ(a.targets[i].x.x, b.targets[i].x.x);
    EXPECT_EQ(a.targets[i].x.y, b.targets[i].x.y);
    EXPECT_EQ(a.targets[i].x.z, b.targets[i].x.z);
    EXPECT_EQ(a.targets[i].r, b.targets[i].r);
  }
  ASSERT_EQ(a.pushes.size(), b.pushes.size());
  for (std::size_t i = 0; i < a.pushes.size(); ++i) {
    EXPECT_EQ(a.pushes[i].id, b.pushes[i].id);
    EXPECT_EQ(a.pushes[i].dx.x, b.pushes[i].dx.x);
    EXPECT_EQ(a.pushes[i].dx.y, b.pushes[i].dx.y);
    EXPECT_EQ(a.pushes[i].dx.z, b.pushes[i].dx.z);
  }
}

}    // namespace

TEST(Engine, FitModeRelocatesBarOverlapsWithoutOverlap)
{
  Scene s = make_scene(1);
  Settings st = default_settings(SizeMode::Fit);
  st.displaced = 2;    // the paper tries every target
  mark(s, st.tol);
  Stats stats;
  const Relocation rel = relocate_targets(s.particles, st, s.domain, false, stats);
  ASSERT_GT(stats.targets, 10);
  EXPECT_EQ(stats.targets, static_cast<std::int64_t>(rel.targets.size()));
  EXPECT_EQ(stats.targets, stats.relocated + stats.unplaced);
  EXPECT_TRUE(rel.pushes.empty());    // fit mode moves nothing else
  // A sparse packing has room for nearly every target.
  EXPECT_GE(stats.relocated, 0.9 * stats.targets);
  const auto after = apply(s, rel, false);
  EXPECT_LE(worst_overlap_of_moved(after, s), st.tol);
  EXPECT_LE(stats.max_overlap, st.tol);
  for (const TargetResult &p : rel.targets) {
    if (p.outcome != Outcome::Placed) continue;
    EXPECT_GE(p.r, st.rmin);
    EXPECT_LE(p.r, st.rmax);
    // Wholly inside the non-periodic box.
    for (int d = 0; d < 3; ++d) {
      EXPECT_GE(p.x[d] - p.r, s.domain.lo[d]);
      EXPECT_LE(p.x[d] + p.r, s.domain.hi[d]);
    }
    // Within the neighbourhood searched.
    EXPECT_LE(norm(p.x - s.particles[p.index].x), s.particles[p.index].r + st.search + 1e-12);
  }
  // The counts follow from the placements.
  std::int64_t placed = 0;
  double volume = 0;
  for (const TargetResult &p : rel.targets)
    if (p.outcome == Outcome::Placed) {
      ++placed;
      volume += 4.0 / 3.0 * M_PI * p.r * p.r * p.r;
    }
  EXPECT_EQ(placed, stats.relocated);
  EXPECT_NEAR(volume, stats.volume_after, 1e-12);
}

// Keep mode on a denser packing: every relocated sphere keeps its radius,
// room is made by pushing neighbours, and nothing overlaps afterwards.
// Pushed spheres lie within `zone` of the bar, move at most `push`, and no
// sphere outside that zone moves. Targets mostly inside the bar are
// deleted as displaced.
TEST(Engine, KeepModeKeepsRadiiAndMakesRoom)
{
  Scene s = make_scene(11, 0.03, 0.066);
  for (Particle &p : s.particles)    // the bar between lattice rows, not on one
    if (p.role == Role::Rebar) p.x = p.x + Vec3{0, 0.036, 0.036};
  const Settings st = default_settings();
  mark(s, st.tol);
  Stats stats;
  const Relocation rel = relocate_targets(s.particles, st, s.domain, false, stats);
  ASSERT_GT(stats.targets, 10);
  EXPECT_GT(stats.pushed, 0);
  EXPECT_GT(stats.relocated, stats.targets / 2);
  EXPECT_EQ(stats.targets, stats.relocated + stats.unplaced);
  const std::vector<Particle> after = apply(s, rel, false);
  EXPECT_LE(worst_overlap_of_moved(after, s), st.tol);
  EXPECT_LE(stats.max_overlap, st.tol);
  int kept_radius = 0;
  for (const TargetResult &t : rel.targets) {
    const Particle &before = s.particles[t.index];
    if (t.outcome == Outcome::Placed) {
      // Its own radius, or (jammed around it) the radius of a void in range.
      kept_radius += t.r == before.r;
      if (t.r != before.r) {
        EXPECT_GE(t.r, st.rmin);
        EXPECT_LE(t.r, st.rmax);
      }
      EXPECT_LE(norm(t.x - before.x), before.r + st.search + 1e-12);
    } else if (t.outcome == Outcome::Displaced) {
      // Its centre lies in the bar, up to the sampling of the volume fraction.
      double depth = INFINITY;
      for (const Particle &q : s.particles)
        if (q.role == Role::Rebar) depth = std::min(depth, norm(q.x - before.x) - q.r);
      EXPECT_LT(depth, 0.1 * before.r);
    }
  }
  EXPECT_GT(kept_radius, stats.relocated / 2);
  double largest = 0;
  for (const Push &p : rel.pushes) {
    largest = std::max(largest, norm(p.dx));
    for (const Particle &q : s.particles) {
      if (q.id != p.id) continue;
      EXPECT_EQ(q.role, Role::Matrix);
      double gap = INFINITY;
      for (const Particle &b : s.particles)
        if (b.role == Role::Rebar) gap = std::min(gap, norm(b.x - q.x) - b.r - q.r);
      EXPECT_LE(gap, st.zone);
    }
  }
  EXPECT_LE(largest, st.push);
  EXPECT_NEAR(largest / st.rmin, stats.max_push, 1e-12);
  // The displaced volume is what the fix removes.
  double removed = 0;
  for (const TargetResult &t : rel.targets)
    if (t.outcome != Outcome::Placed)
      removed += 4.0 / 3.0 * M_PI * std::pow(s.particles[t.index].r, 3);
  EXPECT_NEAR(removed, stats.volume_removed, 1e-12);
}

// size keep without pushing (the default): a target keeps its radius
// where a void tangent to three spheres holds it, else takes the void it
// fits (the paper's placement); nothing else moves, nothing overlaps, and
// the largest targets go first. On this sparse packing most keep their
// radius, and the radii change less than with size fit.
TEST(Engine, KeepModeWithoutPushKeepsRadiiWhereAVoidHoldsThem)
{
  Scene s = make_scene(1);
  Settings st;
  Stats stats;
  const Relocation rel = relocate_keep_without_push(s, st, stats);
  ASSERT_GT(stats.targets, 10);
  EXPECT_TRUE(rel.pushes.empty());
  EXPECT_EQ(stats.pushed, 0);
  EXPECT_EQ(stats.sweeps, 0);
  const std::vector<Particle> after = apply(s, rel, false);
  EXPECT_LE(worst_overlap_of_moved(after, s), st.tol);
  int own = 0;
  double previous = INFINITY;
  for (const TargetResult &t : rel.targets) {
    const Particle &before = s.particles[t.index];
    EXPECT_LE(before.r, previous);    // largest first
    previous = before.r;
    if (t.outcome != Outcome::Placed) continue;
    EXPECT_LE(norm(t.x - before.x), before.r + st.search + 1e-12);
    if (t.r == before.r) {
      ++own;
    } else {
      EXPECT_GE(t.r, st.rmin);
      EXPECT_LE(t.r, st.rmax);
    }
  }
  EXPECT_GT(own, stats.targets / 2);
  // The radii change less than with size fit (which takes each void's).
  Settings fit = st;
  fit.size = SizeMode::Fit;
  Stats fit_stats;
  const Relocation fitted = relocate_targets(s.particles, fit, s.domain, false, fit_stats);
  auto radius_change = [&](const Relocation &r) {
    double sum = 0;
    for (const TargetResult &t : r.targets)
      if (t.outcome == Outcome::Placed) sum += std::fabs(t.r - s.particles[t.index].r);
    return sum;
  };
  EXPECT_LT(radius_change(rel), 0.5 * radius_change(fitted));
}

// The targets placed with a radius below their own are counted; with the
// regrowth on they are listed with where they were and their own radius,
// for the regrowth; with it off none is. (Size fit: most targets take a
// smaller void's radius.)
TEST(Engine, ShrunkTargetsAreListedForTheRegrowth)
{
  for (const double regrow : {0.0, 0.05}) {
    Scene s = make_scene(3, 0.008);
    Settings st = default_settings(SizeMode::Fit);
    st.displaced = 2;
    st.regrow = regrow;
    mark(s, st.tol);
    Stats stats;
    const Relocation rel = relocate_targets(s.particles, st, s.domain, false, stats);
    std::vector<std::int64_t> shrunk;
    for (const TargetResult &t : rel.targets)
      if (t.outcome == Outcome::Placed && t.r < s.particles[t.index].r) shrunk.push_back(t.id);
    ASSERT_GT(shrunk.size(), 0u) << regrow;
    EXPECT_EQ(stats.shrunk, static_cast<std::int64_t>(shrunk.size()));
    if (regrow == 0) {
      EXPECT_TRUE(rel.placed_shrunk.empty());
      continue;
    }
    ASSERT_EQ(rel.placed_shrunk.size(), shrunk.size());
    for (std::size_t k = 0; k < shrunk.size(); ++k) {
      const ShrunkTarget &t = rel.placed_shrunk[k];
      EXPECT_EQ(t.id, shrunk[k]);
      bool found = false;
      for (const Particle &p : s.particles)
        found = found || (p.id == t.id && p.x.x == t.x0.x && p.x.y == t.x0.y && p.x.z == t.x0.z &&
                          p.r == t.r0);
      EXPECT_TRUE(found) << t.id;
    }
  }
}

TEST(Engine, TargetsAreExactlyTheSpheresOverlappingRebar)
{
  Scene s = make_scene(2);
  const double tol = 1e-6;
  const auto targets = find_targets(s.particles, tol);
  std::size_t expected = 0;
  for (const Particle &p : s.particles) {
    if (p.role == Role::Rebar) continue;
    bool hit = false;
    for (const Particle &q : s.particles)
      if (q.role == Role::Rebar && p.r + q.r - norm(p.x - q.x) > tol * std::min(p.r, q.r))
        hit = true;
    expected += hit;
  }
  EXPECT_EQ(targets.size(), expected);
  EXPECT_GT(expected, 0u);
}

TEST(Engine, ChooseClosestKeepsSizeBetterThanFirst)
{
  Scene s = make_scene(3);
  Settings st = default_settings(SizeMode::Fit);
  mark(s, st.tol);
  double err[2];
  for (Choice c : {Choice::First, Choice::Closest}) {
    st.choice = c;
    Stats stats;
    const Relocation placements = relocate_targets(s.particles, st, s.domain, false, stats);
    double sum = 0;
    int n = 0;
    for (const TargetResult &p : placements.targets)
      if (p.outcome == Outcome::Placed) {
        sum += std::fabs(p.r - s.particles[p.index].r);
        ++n;
      }
    ASSERT_GT(n, 0);
    err[c == Choice::Closest] = sum / n;
    const auto after = apply(s, placements, false);
    EXPECT_LE(worst_overlap_of_moved(after, s), st.tol);
  }
  EXPECT_LT(err[1], err[0]);
}

// The same scene in another order (as another process count would list its
// atoms) gives the same results, bit for bit.
TEST(Engine, SameInputSameOutputInAnyOrder)
{
  Scene s = make_scene(4);
  const Settings st = default_settings();
  mark(s, st.tol);
  Scene shuffled = s;
  std::mt19937_64 rng(4);
  std::shuffle(shuffled.particles.begin(), shuffled.particles.end(), rng);
  Stats a, b;
  const Relocation pa = relocate_targets(s.particles, st, s.domain, false, a);
  const Relocation pb = relocate_targets(shuffled.particles, st, shuffled.domain, false, b);
  ASSERT_GT(pa.targets.size(), 0u);
  expect_same_relocation(pa, pb);
  EXPECT_EQ(a.solves, b.solves);
}

TEST(Engine, NoTargetsNoWork)
{
  Scene s = make_scene(5, 0.03);
  for (Particle &p : s.particles)
    if (p.role == Role::Rebar) p.x.y = 5;    // bar moved out of the packing
  const Settings st = default_settings();
  mark(s, st.tol);
  Stats stats;
  EXPECT_TRUE(relocate_targets(s.particles, st, s.domain, false, stats).targets.empty());
  EXPECT_EQ(stats.targets, 0);
  EXPECT_EQ(stats.solves, 0);
}

// A packing with no room (radius range that no void fits): every target is
// unplaced; `keep` leaves them present, so later targets avoid them.
TEST(Engine, UnplacedAreCountedAndKeptOnRequest)
{
  Scene s = make_scene(6);
  Settings st = default_settings(SizeMode::Fit);
  st.displaced = 2;
  st.rmin = st.rmax = 0.2;    // nothing that large fits anywhere
  mark(s, st.tol);
  Stats stats;
  relocate_targets(s.particles, st, s.domain, true, stats);
  EXPECT_GT(stats.targets, 0);
  EXPECT_EQ(stats.relocated, 0);
  EXPECT_EQ(stats.unplaced, stats.targets);
  EXPECT_EQ(stats.volume_after, 0);
}

// Tries bound the work: at most `tries` kernel solves per target.
TEST(Engine, TriesBoundTheSolves)
{
  Scene s = make_scene(7);
  Settings st = default_settings(SizeMode::Fit);
  st.tries = 5;
  st.choice = Choice::Closest;
  mark(s, st.tol);
  Stats stats;
  relocate_targets(s.particles, st, s.domain, false, stats);
  EXPECT_GT(stats.targets, 0);
  EXPECT_LE(stats.solves, 5 * stats.targets);
}

// Periodic x: the bar crosses the periodic boundary and the process sees its
// own atoms' periodic images as ghosts (as one LAMMPS process does). New
// spheres must not overlap anything under the minimum image.
TEST(Engine, PeriodicImagesAreRespected)
{
  Scene s = make_scene(8);
  s.domain.periodic[0] = true;
  const double cut = 0.2;
  s.domain.view_lo = {-cut, -cut, -cut};
  s.domain.view_hi = {1 + cut, 0.5 + cut, 0.5 + cut};
  std::vector<Particle> with_ghosts = s.particles;
  for (const Particle &p : s.particles)
    for (int shift : {-1, 1}) {
      Particle g = p;
      g.x.x += shift;
      g.owned = false;
      if (g.x.x >= -cut && g.x.x <= 1 + cut) with_ghosts.push_back(g);
    }
  s.particles = with_ghosts;
  Settings st = default_settings();
  mark(s, st.tol);
  // Ghost copies of owned targets are targets too (the host forwards that).
  std::vector<std::int64_t> target_ids;
  for (const Particle &p : s.particles)
    if (p.role == Role::Target) target_ids.push_back(p.id);
  for (Particle &p : s.particles)
    for (std::int64_t id : target_ids)
      if (p.id == id) p.role = Role::Target;
  Stats stats;
  const Relocation placements = relocate_targets(s.particles, st, s.domain, false, stats);
  ASSERT_GT(stats.relocated, 0);
  // Final owned spheres, wrapped into the box, checked under minimum image.
  std::vector<Particle> owned;
  for (const Particle &p : apply(s, placements, false))
    if (p.owned) owned.push_back(p);
  // Pre-existing packing has no overlaps except matrix-on-rebar targets that
  // were deleted; the bar's own spheres overlap each other (a clump).
  double worst_matrix = -INFINITY;
  for (std::size_t i = 0; i < owned.size(); ++i)
    for (std::size_t j = 0; j < owned.size(); ++j) {
      if (i == j || owned[i].role == Role::Rebar) continue;
      Vec3 d = owned[i].x - owned[j].x;
      d.x -= std::round(d.x);
      worst_matrix = std::max(worst_matrix, (owned[i].r + owned[j].r - norm(d)) /
                                                std::min(owned[i].r, owned[j].r));
    }
  EXPECT_LE(worst_matrix, st.tol);
}

// The schedule hands a round only the particles within the read reach of
// its targets (the largest target radius, the largest radius of the view):
// a relocation must give the same result from them as from the whole view,
// with and without pushing (docs/design.md, "What a round reads").
TEST(Engine, ParticlesBeyondTheReadReachChangeNothing)
{
  for (const double push : {0.0, kRmax}) {
    for (const SizeMode size : {SizeMode::Keep, SizeMode::Fit}) {
      Scene s = make_scene(5);
      Settings st = default_settings(size);
      st.push = push;
      mark(s, st.tol);
      // Half the targets, as one round of one process would have.
      auto mine = [](const Particle &p) { return p.role == Role::Target && p.x.x < 0.5; };
      double target_rmax = 0, largest = st.rmax;
      for (const Particle &p : s.particles) {
        largest = std::max(largest, p.r);
        if (mine(p)) target_rmax = std::max(target_rmax, p.r);
      }
      const double reach = footprint(st, target_rmax, largest).read;
      std::vector<Particle> near;
      for (const Particle &p : s.particles) {
        bool within = false;
        for (const Particle &t : s.particles)
          within = within || (mine(t) && norm(t.x - p.x) <= reach);
        if (within) near.push_back(p);
      }
      ASSERT_LT(near.size(), s.particles.size());
      Stats a, b;
      const Relocation whole = relocate_targets(s.particles, st, s.domain, false, a, mine);
      const Relocation part = relocate_targets(near, st, s.domain, false, b, mine);
      ASSERT_GE(whole.targets.size(), 4u);
      expect_same_relocation(whole, part);
      EXPECT_EQ(a.solves, b.solves);
    }
  }
}

TEST(Engine, FootprintCoversWhatARelocationTouches)
{
  Settings st = default_settings(SizeMode::Fit);
  Footprint f = footprint(st, kRmax, 0.1);
  EXPECT_DOUBLE_EQ(f.write, kRmax + st.search);
  EXPECT_DOUBLE_EQ(f.read, kRmax + st.search + st.rmax + 0.1);
  st.size = SizeMode::Keep;
  f = footprint(st, kRmax, 0.1);
  // New centre within r + search, pushed spheres start within r + 2 rmax of
  // it and move at most `push`.
  EXPECT_DOUBLE_EQ(f.write, kRmax + st.search + kRmax + 2 * st.rmax + st.push);
  EXPECT_GE(f.read, f.write + st.zone + st.rmax + 0.1);
}

TEST(Engine, SpheresNearRebarFindsOnlyThoseWithinMargin)
{
  // A rebar sphere at the origin (r = 1) and matrix spheres along x.
  double pos[6][3] = {{0, 0, 0}, {2.5, 0, 0}, {3.4, 0, 0}, {3.6, 0, 0}, {-3.4, 0, 0}, {0, 10, 0}};
  const double *x[6];
  for (int i = 0; i < 6; ++i) x[i] = pos[i];
  const double radius[6] = {1, 0.5, 0.5, 0.5, 0.5, 0.5};
  const unsigned char rebar[6] = {1, 0, 0, 0, 0, 0};
  // Gaps to the rebar surface: 1.0, 1.9, 2.1, 1.9, 8.5.
  const auto near = spheres_near_rebar(6, x, radius, rebar, 2.0);
  EXPECT_EQ(near, (std::vector<int>{0, 1, 2, 4}));
  const unsigned char none[6] = {0, 0, 0, 0, 0, 0};
  EXPECT_TRUE(spheres_near_rebar(6, x, radius, none, 2.0).empty());
}

// Pre-existing overlaps of the packing: each pair counted once over all
// processes. Two processes each see the pair (one owned, one ghost): only
// the owner of the lower id counts it; periodic images of a sphere never
// pair with it; rebar pairs are not counted.
TEST(Engine, PackingOverlapsCountedOncePerPair)
{
  const Particle a{{0, 0, 0}, 1, 10, Role::Matrix, true};
  const Particle b{{1.5, 0, 0}, 1, 20, Role::Matrix, true};    // overlaps a by 0.5
  const Particle bar1{{0, 3, 0}, 1, 30, Role::Rebar, true};
  const Particle bar2{{1, 3, 0}, 1, 31, Role::Rebar, true};    // rebar clump: not counted
  double largest = 0;
  // One process owns both.
  EXPECT_EQ(count_packing_overlaps({a, b, bar1, bar2}, 1e-6, 0.5, largest), 1);
  EXPECT_DOUBLE_EQ(largest, 1.0);    // 0.5 overlap / rmin 0.5
  // Two processes: each owns one and sees the other as a ghost.
  Particle a_ghost = a, b_ghost = b;
  a_ghost.owned = b_ghost.owned = false;
  const std::int64_t on_first = count_packing_overlaps({a, b_ghost}, 1e-6, 0.5, largest);
  const std::int64_t on_second = count_packing_overlaps({b, a_ghost}, 1e-6, 0.5, largest);
  EXPECT_EQ(on_first + on_second, 1);
  // A periodic image of a sphere is not a partner of the sphere itself.
  Particle a_image = a;
  a_image.owned = false;
  a_image.x.x = 1.0;
  EXPECT_EQ(count_packing_overlaps({a, a_image}, 1e-6, 0.5, largest), 0);
  // Touching within tol is no overlap.
  const Particle c{{2, 0, 0}, 1, 40, Role::Matrix, true};
  EXPECT_EQ(count_packing_overlaps({a, c}, 1e-6, 0.5, largest), 0);
}

// Wrapping and periodic images (what every process applies to its view
// between rounds, and what a placed sphere adds): a centre past the top
// edge comes back by one period, one far out by several; a corner of a
// fully periodic box has 8 copies in a view that covers the box and a
// margin; non-periodic dimensions give no image; the centre is left out on
// request.
TEST(Engine, WrappingAndImagesInView)
{
  Domain d;
  d.lo = {0, 0, 0};
  d.hi = {1, 2, 4};
  d.periodic[0] = d.periodic[1] = d.periodic[2] = true;
  d.view_lo = {-0.1, -0.1, -0.1};
  d.view_hi = {1.1, 2.1, 4.1};
  const Vec3 w = wrapped_into_box({1.25, -0.5, 9.0}, d);
  EXPECT_DOUBLE_EQ(w.x, 0.25);
  EXPECT_DOUBLE_EQ(w.y, 1.5);
  EXPECT_DOUBLE_EQ(w.z, 1.0);
  const Vec3 inside{0.5, 1, 2};
  EXPECT_EQ(wrapped_into_box(inside, d).x, inside.x);    // unchanged, bit for bit
  EXPECT_EQ(images_in_view({0.05, 0.05, 0.05}, d, true).size(), 8u);
  EXPECT_EQ(images_in_view({0.05, 0.05, 0.05}, d, false).size(), 7u);
  EXPECT_EQ(images_in_view({0.5, 1, 2}, d, true).size(), 1u);
  d.periodic[1] = d.periodic[2] = false;
  EXPECT_EQ(images_in_view({0.05, 0.05, 0.05}, d, true).size(), 2u);
  EXPECT_EQ(wrapped_into_box({1.25, -0.5, 9.0}, d).y, -0.5);    // not periodic: as is
  // Outside the view: nothing, not even the centre.
  EXPECT_TRUE(images_in_view({0.5, 1, 9}, d, true).empty());
}

// The grid against brute force: every point within the range of a query is
// listed exactly once (here, on a grid whose cells are smaller than the
// range, so a query spans many cells), also far from the origin, at negative
// coordinates, after erasing and moving points, past many table growths;
// and insert_around lists a point in the one cell of every point within a
// cell size of it.
TEST(CellGrid, QueriesMatchBruteForce)
{
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unif(-1, 1);
  for (const Vec3 offset : {Vec3{0, 0, 0}, Vec3{-3e3, 1e4, -7e2}}) {
    const double cell = 0.05;
    CellGrid grid(cell);
    std::vector<Vec3> x(3000);
    std::vector<bool> present(x.size(), true);
    for (std::size_t i = 0; i < x.size(); ++i) {
      x[i] = offset + Vec3{unif(rng), unif(rng), unif(rng)};
      grid.insert(x[i], static_cast<int>(i));
    }
    for (std::size_t i = 0; i < x.size(); i += 7) {
      grid.erase(x[i], static_cast<int>(i));
      present[i] = false;
    }
    for (std::size_t i = 3; i < x.size(); i += 11) {
      if (!present[i]) continue;
      const Vec3 to = x[i] + Vec3{0.2 * unif(rng), 0.2 * unif(rng), 0.2 * unif(rng)};
      grid.move(x[i], to, static_cast<int>(i));
      x[i] = to;
    }
    for (int q = 0; q < 200; ++q) {
      const Vec3 c = offset + Vec3{1.2 * unif(rng), 1.2 * unif(rng), 1.2 * unif(rng)};
      const double range = 0.03 + 0.15 * (unif(rng) + 1);
      std::vector<int> seen(x.size(), 0);
      grid.for_each_near(c, range, [&](int i) { ++seen[i]; });
      for (std::size_t i = 0; i < x.size(); ++i) {
        EXPECT_LE(seen[i], present[i] ? 1 : 0);
        if (present[i] && norm(x[i] - c) <= range) {
          EXPECT_EQ(seen[i], 1) << i;
        }
      }
    }
    CellGrid around(cell);
    for (std::size_t i = 0; i < 500; ++i) around.insert_around(x[i], static_cast<int>(i));
    for (int q = 0; q < 300; ++q) {
      const Vec3 c = offset + Vec3{unif(rng), unif(rng), unif(rng)};
      std::vector<int> seen(500, 0);
      around.for_each_in_cell(c, [&](int i) { ++seen[i]; });
      for (std::size_t i = 0; i < 500; ++i) {
        EXPECT_LE(seen[i], 1);
        if (norm(x[i] - c) <= cell) {
          EXPECT_EQ(seen[i], 1) << i;
        }
      }
    }
  }
}

// No cell size, point or range makes the grid throw, overflow or miss an
// item: a size that is not positive and finite gives one cell; a query box
// over more cells than the grid holds (a huge or infinite range, points
// far out) visits every cell once.
TEST(CellGrid, DegenerateSizesPointsAndRangesMissNothing)
{
  const std::vector<Vec3> x = {{0, 0, 0}, {1, 2, 3}, {-5, 1e6, 0.5}, {1e300, -1e300, 0}};
  auto found = [&](const CellGrid &g, Vec3 c, double range) {
    std::vector<int> seen(x.size(), 0);
    g.for_each_near(c, range, [&](int i) { ++seen[i]; });
    return seen;
  };
  for (double size : {0.0, -1.0, static_cast<double>(NAN), static_cast<double>(INFINITY), 1e-320}) {
    CellGrid g(size);
    for (std::size_t i = 0; i < x.size(); ++i) g.insert(x[i], static_cast<int>(i));
    for (int s : found(g, {0, 0, 0}, 0.1)) EXPECT_EQ(s, 1) << size;
  }
  CellGrid g(0.5);
  for (std::size_t i = 0; i < x.size(); ++i) g.insert(x[i], static_cast<int>(i));
  for (double range : {1e305, static_cast<double>(INFINITY), static_cast<double>(NAN)})
    for (int s : found(g, {0, 0, 0}, range)) EXPECT_EQ(s, 1) << range;
  // A point far out (its cell clamped) is found near itself.
  EXPECT_EQ(found(g, {1e300, -1e300, 0}, 1.0)[3], 1);
  // A NaN point names some cell (callers test exact distances, which a
  // NaN fails): no crash, no item twice.
  for (int s : found(g, {static_cast<double>(NAN), 0, 0}, 1.0)) EXPECT_LE(s, 1);
  g.erase(x[3], 3);
  EXPECT_EQ(found(g, {0, 0, 0}, static_cast<double>(INFINITY))[3], 0);
}
