// Regrowth tests on small hand-made scenes in an in-memory host of one
// process (periodic images as its ghosts): targets left without a void or
// placed shrunk, the bars they overlap, the matrix around them.
#include "reinforce_ball_sample.h"
#include "reinforce_exact_sum.h"
#include "reinforce_regrowth.h"
#include "reinforce_regrowth_count.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <stdexcept>

using namespace reinforce;

namespace {

// The promise: a moved sphere overlaps nothing by more than 1e-12 of the
// smaller radius (rounding). The test's own bound, not the engine's
// constant: loosening that must fail these tests.
constexpr double kExact = 1e-12;
constexpr int kGroup = 1, kRebar = 2;

struct Atom {
  Vec3 x;
  double r = 0;
  std::int64_t id = 0;
  int mask = kGroup;
  int pending = 0;
};

// One process over a box, periodic or not; its ghosts are the periodic
// images of its atoms within `cutoff` of the box, as a host makes them.
class RegrowthHost : public HostHooks {
public:
  std::vector<Atom> atoms_;
  Domain box;
  double cutoff = 0;
  std::int64_t forwards = 0;

  RegrowthHost(double half, bool periodic = false)
  {
    box.lo = {-half, -half, -half};
    box.hi = {half, half, half};
    for (int d = 0; d < 3; ++d) box.periodic[d] = periodic;
  }
  std::int64_t add(Vec3 x, double r, int mask = kGroup, bool pending = false)
  {
    const std::int64_t id = static_cast<std::int64_t>(atoms_.size()) + 1;
    atoms_.push_back({x, r, id, mask, pending ? 1 : 0});
    return id;
  }
  const Atom *find(std::int64_t id) const
  {
    for (const Atom &a : atoms_)
      if (a.id == id) return &a;
    return nullptr;
  }

  void refresh() override
  {
    ghost_of_.clear();
    shift_.clear();
    for (std::size_t i = 0; i < atoms_.size(); ++i)
      for (int sx = -1; sx <= 1; ++sx)
        for (int sy = -1; sy <= 1; ++sy)
          for (int sz = -1; sz <= 1; ++sz) {
            const int s[3] = {sx, sy, sz};
            Vec3 shift;
            bool image = sx || sy || sz, inside = image;
            for (int d = 0; d < 3 && inside; ++d) {
              if (s[d] && !box.periodic[d]) inside = false;
              shift[d] = s[d] * (box.hi[d] - box.lo[d]);
              const double c = atoms_[i].x[d] + shift[d];
              inside = inside && c >= box.lo[d] - cutoff && c <= box.hi[d] + cutoff;
            }
            if (!inside) continue;
            ghost_of_.push_back(static_cast<int>(i));
            shift_.push_back(shift);
          }
  }
  AtomArrays atoms() override
  {
    const std::size_t n = atoms_.size(), g = ghost_of_.size();
    pos_.resize(n + g);
    radius_.resize(n + g);
    tag_.resize(n + g);
    mask_.resize(n + g);
    pending_.resize(n + g);
    for (std::size_t k = 0; k < n + g; ++k) {
      const Atom &a = atoms_[k < n ? k : static_cast<std::size_t>(ghost_of_[k - n])];
      const Vec3 x = k < n ? a.x : a.x + shift_[k - n];
      pos_[k] = {x.x, x.y, x.z};
      radius_[k] = a.r;
      tag_[k] = a.id;
      mask_[k] = a.mask;
      pending_[k] = a.pending;
    }
    rows_.clear();
    for (auto &p : pos_) rows_.push_back(p.data());
    AtomArrays out;
    out.nlocal = static_cast<int>(n);
    out.nall = static_cast<int>(n + g);
    out.x = rows_.data();
    out.radius = radius_.data();
    out.tag64 = tag_.data();
    out.mask = mask_.data();
    out.pending = pending_.data();
    out.group_bit = kGroup;
    out.rebar_bit = kRebar;
    return out;
  }
  void set_pending(int i, bool p) override { atoms_[i].pending = p; }
  void forward_pending() override {}
  GhostCutoff ensure_ghost_cutoff(double reach) override
  {
    cutoff = std::max(cutoff, reach);
    return {};
  }
  void restore_ghost_cutoff() override {}
  Domain placement_domain() override
  {
    Domain d = box;
    for (int k = 0; k < 3; ++k) {
      d.view_lo[k] = d.lo[k] - cutoff;
      d.view_hi[k] = d.hi[k] + cutoff;
      d.sub_lo[k] = d.lo[k];
      d.sub_hi[k] = d.hi[k];
    }
    return d;
  }
  void move(int i, Vec3 x, double r) override
  {
    atoms_[i].x = x;
    atoms_[i].r = r;
    atoms_[i].pending = 0;
  }
  void remove(std::vector<int> &locals) override
  {
    std::sort(locals.rbegin(), locals.rend());
    for (int i : locals) atoms_.erase(atoms_.begin() + i);
  }
  double sum(double v) override { return v; }
  double max(double v) override { return v; }
  void sum_and_max(std::vector<double> &, std::vector<double> &) override {}
  void forward(std::vector<double> &values, int width, bool positions) override
  {
    ++forwards;
    const std::size_t n = atoms_.size();
    for (std::size_t g = 0; g < ghost_of_.size(); ++g)
      for (int c = 0; c < width; ++c)
        values[(n + g) * width + c] =
            values[ghost_of_[g] * width + c] + (positions && c < 3 ? shift_[g][c] : 0.0);
  }
  std::vector<double> gather_all(const std::vector<double> &mine) override { return mine; }
  void post_results(const std::vector<double> &, const std::vector<int> &) override {}
  std::vector<double> collect_results(const std::vector<int> &) override { return {}; }
  void finish_results() override {}
  // A clock that advances `tick` seconds a reading (0: stands still).
  double tick = 0, clock = 0;
  double wall_time() override { return clock += tick; }
  std::vector<std::string> logged;
  void log(const std::string &line) override { logged.push_back(line); }
  void warn(const std::string &) override {}
  void fail(const std::string &message) override { throw std::runtime_error(message); }

private:
  std::vector<int> ghost_of_;
  std::vector<Vec3> shift_;
  std::vector<std::array<double, 3>> pos_;
  std::vector<double *> rows_;
  std::vector<double> radius_;
  std::vector<std::int64_t> tag_;
  std::vector<int> mask_, pending_;
};

// The regrowth of the host's pending atoms and `shrunk`, in a zone of
// `width`, as an invocation runs it.
RegrowthStats regrow_scene(RegrowthHost &h, double width, std::vector<ShrunkTarget> shrunk = {})
{
  RegrowthInput in;
  in.settings.tol = 1e-6;
  in.width = width;
  in.matrix_rmin = INFINITY;
  for (const Atom &a : h.atoms_) {
    in.largest = std::max(in.largest, a.r);
    if (a.mask & kRebar) continue;
    in.matrix_rmin = std::min(in.matrix_rmin, a.r);
    in.matrix_rmax = std::max(in.matrix_rmax, a.r);
  }
  for (const ShrunkTarget &t : shrunk) in.matrix_rmax = std::max(in.matrix_rmax, t.r0);
  in.shrunk = std::move(shrunk);
  h.ensure_ghost_cutoff(regrowth_ghost_reach(in.matrix_rmax, in.largest, 0));
  h.refresh();
  in.domain = h.placement_domain();
  RegrowthStats stats;
  regrow(h, in, stats);
  return stats;
}

// The largest overlap (over the smaller radius) between two atoms, the
// nearest periodic images, rebar pairs left out.
double worst_overlap(const RegrowthHost &h)
{
  double worst = 0;
  for (std::size_t i = 0; i < h.atoms_.size(); ++i)
    for (std::size_t j = i + 1; j < h.atoms_.size(); ++j) {
      const Atom &a = h.atoms_[i], &b = h.atoms_[j];
      if ((a.mask & kRebar) && (b.mask & kRebar)) continue;
      Vec3 d = a.x - b.x;
      for (int k = 0; k < 3; ++k)
        if (h.box.periodic[k]) {
          const double L = h.box.hi[k] - h.box.lo[k];
          d[k] -= L * std::round(d[k] / L);
        }
      worst = std::max(worst, (a.r + b.r - norm(d)) / std::min(a.r, b.r));
    }
  return worst;
}

// A bar sphere at the origin and a target of the same radius 0.1 on it at
// x = 0.15 (id 2).
void bar_and_target(RegrowthHost &h)
{
  h.add({0, 0, 0}, 0.1, kGroup | kRebar);
  h.add({0.15, 0, 0}, 0.1, kGroup, true);
}

// Spheres that may not move (outside the fix group: obstacles only) on the
// cubic lattice of the target's diameter around it, wherever the bar
// leaves room.
void cage(RegrowthHost &h, Vec3 centre, double r, int n)
{
  for (int i = -n; i <= n; ++i)
    for (int j = -n; j <= n; ++j)
      for (int k = -n; k <= n; ++k) {
        if (!i && !j && !k) continue;
        const Vec3 x = centre + Vec3{2 * r * i, 2 * r * j, 2 * r * k};
        if (norm(x) < 0.1 + r) continue;    // the bar's place
        h.add(x, r, 0);
      }
}

}    // namespace

// A target that overlaps a bar with free space beside it is put back at its
// own radius, clear of the bar, near where it was.
TEST(Regrowth, SeedWithRoomIsPutBackAtItsRadius)
{
  RegrowthHost h(1);
  bar_and_target(h);
  const RegrowthStats s = regrow_scene(h, 0.3);
  EXPECT_EQ(s.seeds, 1);
  EXPECT_EQ(s.regrown, 1);
  EXPECT_EQ(s.deleted, 0);
  const Atom *t = h.find(2);
  ASSERT_NE(t, nullptr);
  EXPECT_EQ(t->r, 0.1);
  EXPECT_EQ(t->pending, 0);
  EXPECT_LE(worst_overlap(h), kExact);
  EXPECT_LT(norm(t->x - Vec3{0.15, 0, 0}), 0.3);
}

// The matrix of the zone moves (never into anything, within the zone), and
// the seed gets its own radius; spheres beyond the zone stay where they
// were, bit for bit.
TEST(Regrowth, ZoneMovesAndStaysClear)
{
  RegrowthHost h(1);
  bar_and_target(h);
  for (int k = 0; k < 6; ++k) {
    const double a = k * 3.14159265358979 / 3;
    h.add({0.15 + 0.02 * (k % 2), 0.21 * std::cos(a), 0.21 * std::sin(a)}, 0.1);
  }
  const std::int64_t far = h.add({0.9, 0.9, 0.9}, 0.1);
  const std::vector<Atom> before = h.atoms_;
  const RegrowthStats s = regrow_scene(h, 0.3);
  EXPECT_EQ(s.regrown + s.deleted, 1);
  EXPECT_GT(s.moved, 0);
  EXPECT_LE(worst_overlap(h), kExact);
  EXPECT_EQ(s.inexact, 0);
  for (const Atom &b : before) {
    const Atom *a = h.find(b.id);
    if (!a) continue;
    EXPECT_TRUE(std::isfinite(a->x.x) && std::isfinite(a->x.y) && std::isfinite(a->x.z));
    // Within the zone's width of the target: how far a sphere may go.
    EXPECT_LE(norm(a->x - b.x), 0.3) << b.id;
  }
  EXPECT_EQ(h.find(far)->x.x, 0.9);
  EXPECT_EQ(h.find(far)->x.y, 0.9);
}

// Enclosed by spheres that may not move, a seed cannot fit: it is deleted
// and nothing else changes.
TEST(Regrowth, SeedWithoutRoomIsDeletedAndTheRestLeftAsItWas)
{
  RegrowthHost h(1);
  bar_and_target(h);
  cage(h, {0.15, 0, 0}, 0.1, 2);
  const std::vector<Atom> before = h.atoms_;
  const RegrowthStats s = regrow_scene(h, 0.3);
  EXPECT_EQ(s.seeds, 1);
  EXPECT_EQ(s.deleted, 1);
  EXPECT_EQ(h.find(2), nullptr);
  EXPECT_EQ(h.atoms_.size() + 1, before.size());
  for (const Atom &b : before)
    if (const Atom *a = h.find(b.id)) EXPECT_EQ(norm2(a->x - b.x), 0) << b.id;
  EXPECT_LE(worst_overlap(h), kExact);
}

// A seed whose centre lies inside a bar sphere is what the bar displaces:
// the count deletes it first, and says so.
TEST(Regrowth, SeedInsideABarIsDisplaced)
{
  RegrowthHost h(1);
  h.add({0, 0, 0}, 0.1, kGroup | kRebar);
  h.add({0.05, 0, 0}, 0.1, kGroup, true);
  const RegrowthStats s = regrow_scene(h, 0.3);
  EXPECT_EQ(s.deleted, 1);
  EXPECT_EQ(s.displaced, 1);
  EXPECT_EQ(h.find(2), nullptr);
}

// A place the box faces refuse is not taken: in a channel as wide as the
// seed, with the face past the bar too near, the seed cannot get out of
// the bar and is deleted; a little farther, it fits.
TEST(Regrowth, BoxFacesRefuseMoves)
{
  for (const double end : {0.25, 0.6}) {
    RegrowthHost h(1);
    h.box.lo = {-0.2, -0.1, -0.1};
    h.box.hi = {end, 0.1, 0.1};
    h.add({0, 0, 0}, 0.1, kGroup | kRebar);
    h.add({0.12, 0, 0}, 0.1, kGroup, true);
    const RegrowthStats s = regrow_scene(h, 0.6);
    EXPECT_EQ(s.regrown, end > 0.5 ? 1 : 0) << end;
    for (const Atom &a : h.atoms_)
      if (!(a.mask & kRebar)) {
        EXPECT_LE(a.x.x + a.r, end) << end;
        EXPECT_GE(a.x.y - a.r, -0.1 - 1e-15) << end;
      }
    EXPECT_LE(worst_overlap(h), kExact);
  }
}

namespace {

// A short bar of two spheres (radius 0.05) in a jittered lattice of spheres
// (radius 0.045, `spacing` apart) in a box of half-width 0.5; those that
// overlap the bar are the targets.
void bar_in_lattice(RegrowthHost &h, double spacing, unsigned seed)
{
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  const Vec3 bars[2] = {{-0.04, 0, 0}, {0.04, 0, 0}};
  for (const Vec3 &b : bars) h.add(b, 0.05, kGroup | kRebar);
  const int n = static_cast<int>(0.45 / spacing);
  for (int i = -n; i <= n; ++i)
    for (int j = -n; j <= n; ++j)
      for (int k = -n; k <= n; ++k) {
        const double r = 0.045;
        Vec3 x{i * spacing, j * spacing, k * spacing};
        for (int d = 0; d < 3; ++d) x[d] += 0.3 * (spacing - 2 * r) * u(rng);
        bool target = false;
        for (const Vec3 &b : bars) target = target || norm(x - b) < 0.05 + r;
        h.add(x, r, kGroup, target);
      }
}

std::map<std::int64_t, Atom> by_id(const RegrowthHost &h)
{
  std::map<std::int64_t, Atom> out;
  for (const Atom &a : h.atoms_) out[a.id] = a;
  return out;
}

}    // namespace

// The order of the host's atoms does not change the result, bit for bit;
// every sphere is finite and exact, nothing moves farther than the zone's
// caps, every target is regrown or deleted.
TEST(Regrowth, OrderFreeFiniteExactAndWithinTheZone)
{
  RegrowthHost a(0.5), b(0.5);
  bar_in_lattice(a, 0.1, 3);
  bar_in_lattice(b, 0.1, 3);
  std::reverse(b.atoms_.begin(), b.atoms_.end());
  const std::map<std::int64_t, Atom> start = by_id(a);
  const RegrowthStats sa = regrow_scene(a, 0.3), sb = regrow_scene(b, 0.3);
  ASSERT_GT(sa.seeds, 0);
  EXPECT_EQ(sa.regrown + sa.deleted, sa.seeds);
  EXPECT_GT(sa.regrown, 0);
  EXPECT_EQ(sa.sweeps, sb.sweeps);
  const auto ra = by_id(a), rb = by_id(b);
  ASSERT_EQ(ra.size(), rb.size());
  for (const auto &p : ra) {
    const Atom &x = p.second, &y = rb.at(p.first);
    EXPECT_EQ(x.x.x, y.x.x);
    EXPECT_EQ(x.x.y, y.x.y);
    EXPECT_EQ(x.x.z, y.x.z);
    EXPECT_EQ(x.r, y.r);
    EXPECT_TRUE(std::isfinite(x.x.x) && std::isfinite(x.x.y) && std::isfinite(x.x.z));
    // kCapShare matrix radii, and a seed pushed out of the bar first.
    EXPECT_LE(norm(x.x - start.at(p.first).x), 3 * 0.045 + 0.2) << p.first;
  }
  EXPECT_LE(worst_overlap(a), kExact);
}

// Across a periodic seam: the zone's spheres near it move with their
// images (the host's forward communication), and nothing overlaps its
// neighbours' images.
TEST(Regrowth, ExactAcrossAPeriodicSeam)
{
  RegrowthHost h(0.5, true);
  bar_in_lattice(h, 0.1, 5);
  for (Atom &a : h.atoms_) {
    a.x.x += 0.45;    // the bar now lies on the seam at x = +-0.5
    if (a.x.x >= 0.5) a.x.x -= 1;
  }
  const RegrowthStats s = regrow_scene(h, 0.3);
  ASSERT_GT(s.seeds, 0);
  EXPECT_GT(s.regrown, 0);
  EXPECT_GT(h.forwards, 2);
  EXPECT_LE(worst_overlap(h), kExact);
}

namespace {

// A thin bar (rebar spheres of radius 0.02, 0.03 apart, along y) through
// (0.03, y, 0), crossing a target of radius 0.1 at the origin: the
// relocation placed it shrunk (radius 0.05) at (0, 0, 0.25), where its atom
// now is.
std::vector<ShrunkTarget> thin_bar_and_shrunk(RegrowthHost &h)
{
  for (double y = -0.3; y <= 0.3 + 1e-12; y += 0.03) h.add({0.03, y, 0}, 0.02, kGroup | kRebar);
  const std::int64_t id = h.add({0, 0, 0.25}, 0.05);
  return {{id, {0, 0, 0}, 0.1}};
}

}    // namespace

// A target placed shrunk goes back at its own radius, clear of the bar,
// counted apart from the targets without a void; nothing is deleted.
TEST(Regrowth, ShrunkGoesBackAtItsRadius)
{
  RegrowthHost h(1);
  std::vector<ShrunkTarget> shrunk = thin_bar_and_shrunk(h);
  const std::int64_t id = shrunk[0].id;
  const RegrowthStats s = regrow_scene(h, 0.3, shrunk);
  EXPECT_EQ(s.seeds, 0);
  EXPECT_EQ(s.shrunk_seeds, 1);
  EXPECT_EQ(s.shrunk_regrown, 1);
  EXPECT_EQ(s.deleted, 0);
  ASSERT_NE(h.find(id), nullptr);
  EXPECT_EQ(h.find(id)->r, 0.1);
  EXPECT_NEAR(s.volume_unshrunk, ball_volume(0.1) - ball_volume(0.05), 1e-15);
  EXPECT_EQ(s.volume_regrown, 0);
  EXPECT_LE(worst_overlap(h), kExact);
}

// Caged by spheres that may not move, a shrunk target cannot grow back: it
// stays shrunk, where it was, and nothing is deleted.
TEST(Regrowth, ShrunkThatCannotGrowBackStaysShrunk)
{
  RegrowthHost h(1);
  std::vector<ShrunkTarget> shrunk = thin_bar_and_shrunk(h);
  const std::int64_t id = shrunk[0].id;
  for (int i = -2; i <= 2; ++i)
    for (int j = -2; j <= 2; ++j)
      for (int k = -2; k <= 2; ++k) {
        const Vec3 x{0.1 * i, 0.1 * j, 0.25 + 0.1 * k};
        if (norm(x - Vec3{0, 0, 0.25}) < 0.1 || std::fabs(x.x - 0.03) < 0.07) continue;
        h.add(x, 0.05, 0);
      }
  const std::size_t atoms = h.atoms_.size();
  const RegrowthStats s = regrow_scene(h, 0.3, shrunk);
  EXPECT_EQ(s.shrunk_seeds, 1);
  EXPECT_EQ(s.shrunk_regrown, 0);
  EXPECT_EQ(h.atoms_.size(), atoms);
  ASSERT_NE(h.find(id), nullptr);
  EXPECT_EQ(h.find(id)->r, 0.05);
  EXPECT_LE(worst_overlap(h), kExact);
}

// The count from the volume balance: the seeds deleted are the first in
// the order of depth (deepest first, equal depths by id), their volume (a
// shrunk one's: what it lost) the nearest, a seed at a time, to the share
// times the seeds' volume inside the bars.
TEST(Regrowth, CountFromTheVolume)
{
  std::vector<Seed> seeds;
  const double V = ball_volume(1);
  for (int k = 0; k < 10; ++k) {
    Seed s;
    s.id = 10 - k;
    s.R = 1;
    s.depth = k < 5 ? -0.5 + 0.1 * k : 0.3;    // five equal depths at the end
    s.inside = 0.25 * V;
    seeds.push_back(s);
  }
  std::sort(seeds.begin(), seeds.end(), [](const Seed &a, const Seed &b) { return a.id < b.id; });
  count_kept(seeds, 1.3);    // goal 1.3 x 2.5 V = 3.25 V: three deleted (3 V), 4 would be 4 V
  std::vector<std::int64_t> deleted;
  for (const Seed &s : seeds)
    if (!s.kept) deleted.push_back(s.id);
  EXPECT_EQ(deleted, (std::vector<std::int64_t>{8, 9, 10}));
  // A shrunk seed counts what it lost: half its volume lost, two of them
  // weigh one whole seed (goal 1.2 x 2.5 V: six deleted); equal depths go
  // by id (the five of depth 0.3, ids 1 to 5, after the five deeper).
  for (Seed &s : seeds) s.r = std::cbrt(0.5);
  count_kept(seeds, 1.2);
  deleted.clear();
  for (const Seed &s : seeds)
    if (!s.kept) deleted.push_back(s.id);
  EXPECT_EQ(deleted, (std::vector<std::int64_t>{1, 6, 7, 8, 9, 10}));
  for (Seed &s : seeds) {
    s.r = 0;
    s.inside = 0.9 * V;    // goal 11.7 V: all ten deleted
  }
  count_kept(seeds, 1.3);
  for (const Seed &s : seeds) EXPECT_FALSE(s.kept) << s.id;
  for (Seed &s : seeds) s.inside = 0;    // nothing inside: all kept
  count_kept(seeds, 1.3);
  for (const Seed &s : seeds) EXPECT_TRUE(s.kept) << s.id;
}

// Degenerate scenes: a seed alone with a bar and no matrix around; a bar
// of zero volume inside nothing (nothing to balance: every seed grown
// back); no seed at all (nothing happens).
TEST(Regrowth, DegenerateScenes)
{
  {
    RegrowthHost h(1);
    bar_and_target(h);
    EXPECT_EQ(regrow_scene(h, 1e-3).regrown, 1);
    EXPECT_LE(worst_overlap(h), kExact);
  }
  {
    RegrowthHost h(1);
    h.add({0, 0, 0}, 1e-9, kGroup | kRebar);
    h.add({0, 0, 0.1}, 0.1, kGroup, true);
    const RegrowthStats s = regrow_scene(h, 0.3);
    EXPECT_EQ(s.regrown, 1);
    EXPECT_LE(worst_overlap(h), kExact);
  }
  {
    RegrowthHost h(1);
    h.add({0, 0, 0}, 0.1, kGroup | kRebar);
    h.add({0.5, 0, 0}, 0.1);
    const RegrowthStats s = regrow_scene(h, 0.3);
    EXPECT_EQ(s.seeds + s.shrunk_seeds + s.sweeps, 0);
    EXPECT_EQ(h.find(2)->x.x, 0.5);
  }
}

// Seeds that cannot fit: 125 crowded on a bar in a cage of spheres that
// may not move. They are given up together, within a bounded number of
// FIRE steps whatever the count, and nothing else changes.
TEST(Regrowth, SeedsThatCannotFitAreDeletedTogether)
{
  RegrowthHost h(1);
  h.add({0, 0, 0}, 0.1, kGroup | kRebar);
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 5; ++j)
      for (int k = 0; k < 5; ++k)
        h.add({0.11 + 0.008 * i, -0.016 + 0.008 * j, -0.016 + 0.008 * k}, 0.02, kGroup, true);
  for (int i = -4; i <= 4; ++i)
    for (int j = -4; j <= 4; ++j)
      for (int k = -4; k <= 4; ++k) {
        const Vec3 x{0.04 * i, 0.04 * j, 0.04 * k};
        if (norm(x) < 0.1 + 0.02 || norm(x - Vec3{0.13, 0, 0}) < 0.06) continue;
        h.add(x, 0.02, 0);
      }
  const RegrowthStats s = regrow_scene(h, 0.1);
  EXPECT_EQ(s.seeds, 125);
  EXPECT_GE(s.deleted, 100);
  EXPECT_LE(s.sweeps, 6000);
  EXPECT_LE(worst_overlap(h), kExact);
}

// A regrowth that runs longer than 5 s says how far it got, at most every
// 5 s, on the log: the stage, the steps, the time so far; a quick one
// says nothing of the kind.
TEST(Regrowth, LongGrowthLogsItsProgress)
{
  for (const double tick : {0.0, 1.0}) {
    RegrowthHost h(0.5);
    h.tick = tick;
    bar_in_lattice(h, 0.1, 3);
    regrow_scene(h, 0.3);
    std::size_t progress = 0;
    for (const std::string &line : h.logged)
      if (line.find("fix reinforce/invert: regrowth: stage ") == 0) {
        ++progress;
        EXPECT_NE(line.find(" of 10 (radii "), std::string::npos) << line;
        EXPECT_NE(line.find(" FIRE steps, "), std::string::npos) << line;
        EXPECT_NE(line.find(" s\n"), std::string::npos) << line;
      }
    if (tick == 0)
      EXPECT_EQ(progress, 0u);
    else
      EXPECT_GE(progress, 2u);
  }
}

// Exact sums: the same whatever the order or grouping of the terms, and
// through limbs summed as doubles (as processes add them); a NaN adds
// nothing, a huge term is clamped, a tiny one rounded to a quantum.
TEST(ExactSum, OrderAndGroupingFree)
{
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<double> terms;
  for (int k = 0; k < 1000; ++k) terms.push_back(u(rng) * std::pow(10.0, (k % 12) - 6));
  ExactSum forward(1.0), backward(1.0);
  for (double t : terms) forward.add(t);
  for (auto it = terms.rbegin(); it != terms.rend(); ++it) backward.add(*it);
  EXPECT_EQ(forward.value(), backward.value());
  // Three "processes" of uneven shares, their limbs summed as doubles.
  std::array<double, ExactSum::kLimbs> total{};
  for (int p = 0; p < 3; ++p) {
    ExactSum part(1.0);
    for (std::size_t k = p; k < terms.size(); k += 1 + p) part.add(terms[k]);
    const auto limbs = part.limbs();
    for (int l = 0; l < ExactSum::kLimbs; ++l) total[l] += limbs[l];
  }
  ExactSum whole(1.0);
  for (int p = 0; p < 3; ++p)
    for (std::size_t k = p; k < terms.size(); k += 1 + p) whole.add(terms[k]);
  EXPECT_EQ(ExactSum::from_limbs(total.data(), 1.0), whole.value());
  double plain = 0, size = 0;
  for (double t : terms) {
    plain += t;
    size += std::fabs(t);
  }
  EXPECT_NEAR(forward.value(), plain, 1e-13 * size);
  ExactSum odd(1.0);
  odd.add(NAN);
  odd.add(1e300);
  odd.add(-1e-30);
  EXPECT_TRUE(std::isfinite(odd.value()));
  EXPECT_NEAR(odd.value(), 0x1p62, 0x1p40);
  ExactSum negative(2.0);
  negative.add(-3.0);
  negative.add(-1e20);
  negative.add(1e20);
  EXPECT_EQ(negative.value(), -3.0);
  EXPECT_EQ(ExactSum(0.0).value(), 0.0);    // a bad unit: 1
}
