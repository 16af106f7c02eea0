// The shared invocation driver, on an in-memory host with one process.
#include "invocation.h"

#include <gtest/gtest.h>

#include <cstdio>

#include <cmath>
#include <random>
#include <stdexcept>

using namespace reinforce;

namespace {

constexpr int kGroup = 1, kRebar = 2, kOther = 4;

// One process, non-periodic box [0,1]^3, atoms in plain vectors.
class MemoryHost : public HostHooks {
public:
  std::vector<std::array<double, 3>> pos;
  std::vector<double *> rows;
  std::vector<double> radius, mass;
  std::vector<std::int64_t> tag;
  std::vector<int> mask, pending;
  std::vector<std::string> logged;
  int refreshes = 0;
  double cutoff_asked = 0;

  void add(Vec3 x, double r, int m)
  {
    pos.push_back({x.x, x.y, x.z});
    radius.push_back(r);
    mass.push_back(r * r * r);
    tag.push_back(static_cast<std::int64_t>(tag.size()) + 1);
    mask.push_back(m);
    pending.push_back(0);
  }
  void refresh() override { ++refreshes; }
  AtomArrays atoms() override
  {
    rows.clear();
    for (auto &p : pos) rows.push_back(p.data());
    AtomArrays a;
    a.nlocal = a.nall = static_cast<int>(pos.size());
    a.x = rows.data();
    a.radius = radius.data();
    a.tag = tag;
    a.mask = mask.data();
    a.pending = pending.data();
    a.group_bit = kGroup;
    a.rebar_bit = kRebar;
    return a;
  }
  void set_pending(int i, bool p) override { pending[i] = p; }
  void forward_pending() override {}
  void ensure_ghost_cutoff(double reach) override { cutoff_asked = reach; }
  void restore_ghost_cutoff() override {}
  Domain placement_domain() override
  {
    Domain d;
    d.lo = {0, 0, 0};
    d.hi = d.view_hi = d.sub_hi = {1, 1, 1};
    return d;
  }
  void move(int i, Vec3 x, double r) override
  {
    pos[i] = {x.x, x.y, x.z};
    mass[i] *= std::pow(r / radius[i], 3);
    radius[i] = r;
    pending[i] = 0;
  }
  void remove(std::vector<int> &locals) override
  {
    std::sort(locals.rbegin(), locals.rend());
    for (int i : locals) {
      pos.erase(pos.begin() + i);
      radius.erase(radius.begin() + i);
      mass.erase(mass.begin() + i);
      tag.erase(tag.begin() + i);
      mask.erase(mask.begin() + i);
      pending.erase(pending.begin() + i);
    }
  }
  double sum(double v) override { return v; }
  double max(double v) override { return v; }
  std::vector<double> gather_all(const std::vector<double> &mine) override { return mine; }
  double wall_time() override { return 0; }
  void log(const std::string &line) override { logged.push_back(line); }
  void fail(const std::string &message) override { throw std::runtime_error(message); }
};

// Jittered lattice of matrix spheres (radii 0.02..0.04) with a bar along x.
void fill(MemoryHost &h, unsigned seed)
{
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  const int n = 11;
  const double step = 1.0 / n;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) {
        const double r = 0.02 + 0.02 * u(rng);
        Vec3 c{(i + 0.5) * step, (j + 0.5) * step, (k + 0.5) * step};
        for (int d = 0; d < 3; ++d) c[d] += (step / 2 - r) * (2 * u(rng) - 1);
        h.add(c, r, kGroup);
      }
  for (double x = 0.03; x < 0.97; x += 0.05) h.add({x, 0.5, 0.5}, 0.03, kGroup | kRebar);
}

double worst_matrix_overlap(const MemoryHost &h)
{
  double worst = -INFINITY;
  for (std::size_t i = 0; i < h.pos.size(); ++i) {
    if (h.mask[i] & kRebar) continue;
    for (std::size_t j = 0; j < h.pos.size(); ++j) {
      if (i == j) continue;
      const double d = std::sqrt(std::pow(h.pos[i][0] - h.pos[j][0], 2) +
                                 std::pow(h.pos[i][1] - h.pos[j][1], 2) +
                                 std::pow(h.pos[i][2] - h.pos[j][2], 2));
      worst = std::max(worst, (h.radius[i] + h.radius[j] - d) / std::min(h.radius[i], h.radius[j]));
    }
  }
  return worst;
}

}    // namespace

TEST(Invocation, RelocatesDeletesAndReports)
{
  MemoryHost h;
  fill(h, 1);
  const std::size_t before = h.pos.size();
  const Totals t = run_invocation(h, parse_fix_arguments({"0", "bars"}));
  EXPECT_GT(t.stats.targets, 10);
  EXPECT_EQ(t.stats.targets, t.stats.relocated + t.stats.unplaced);
  EXPECT_EQ(before - h.pos.size(), static_cast<std::size_t>(t.deleted));
  EXPECT_EQ(t.kept, 0);
  EXPECT_LE(worst_matrix_overlap(h), 1e-6);
  for (int p : h.pending) EXPECT_EQ(p, 0);
  // Mass follows volume (density kept).
  for (std::size_t i = 0; i < h.pos.size(); ++i)
    EXPECT_NEAR(h.mass[i], std::pow(h.radius[i], 3), 1e-15);
  // The schedule line (per-process work over the rounds: one process does
  // it all), then the summary line.
  ASSERT_EQ(h.logged.size(), 2u);
  char schedule[200];
  std::snprintf(schedule, sizeof schedule,
                "fix reinforce/invert: schedule: %d rounds, %lld targets, busiest process %lld "
                "targets over the rounds, balance 1.00 over 1 processes\n",
                t.rounds, static_cast<long long>(t.stats.targets),
                static_cast<long long>(t.stats.targets));
  EXPECT_EQ(h.logged[0], schedule);
  EXPECT_EQ(h.logged[1].rfind("fix reinforce/invert: ", 0), 0u);
  EXPECT_GT(h.cutoff_asked, 0);
  // One refresh at the start only: the rounds update the view themselves.
  EXPECT_GE(t.rounds, 1);
  EXPECT_EQ(h.refreshes, 1);
}

TEST(Invocation, KeepLeavesUnplacedInPlace)
{
  MemoryHost h;
  fill(h, 2);
  const std::size_t before = h.pos.size();
  // A radius range no void fits: nothing relocates, everything is kept.
  const Totals t = run_invocation(h, parse_fix_arguments({"0", "bars", "size", "fit", "radius",
                                                          "0.3", "0.3", "unplaced", "keep"}));
  EXPECT_GT(t.stats.targets, 0);
  EXPECT_EQ(t.stats.relocated, 0);
  EXPECT_EQ(t.kept, t.stats.targets);
  EXPECT_EQ(h.pos.size(), before);
  for (int p : h.pending) EXPECT_EQ(p, 0);
}

TEST(Invocation, OnlyFixGroupAtomsAreTargetsButAllAreObstacles)
{
  MemoryHost h;
  fill(h, 3);
  for (std::size_t i = 0; i < h.mask.size(); ++i)
    if (!(h.mask[i] & kRebar) && h.pos[i][0] < 0.5) h.mask[i] = kOther;    // outside the fix group
  const std::size_t before = h.pos.size();
  const Totals t = run_invocation(h, parse_fix_arguments({"0", "bars"}));
  EXPECT_GT(t.stats.targets, 0);
  // Outside the group: untouched even where it overlaps the bar.
  int other = 0;
  for (std::size_t i = 0; i < h.mask.size(); ++i) other += h.mask[i] == kOther;
  EXPECT_GT(other, 0);
  EXPECT_EQ(before - h.pos.size(), static_cast<std::size_t>(t.deleted));
  // Relocated spheres overlap no one, not even atoms outside the group.
  double worst = -INFINITY;
  for (std::size_t i = 0; i < h.pos.size(); ++i) {
    if (h.mask[i] != kGroup) continue;
    for (std::size_t j = 0; j < h.pos.size(); ++j) {
      if (i == j) continue;
      const double d = std::sqrt(std::pow(h.pos[i][0] - h.pos[j][0], 2) +
                                 std::pow(h.pos[i][1] - h.pos[j][1], 2) +
                                 std::pow(h.pos[i][2] - h.pos[j][2], 2));
      worst = std::max(worst, (h.radius[i] + h.radius[j] - d) / std::min(h.radius[i], h.radius[j]));
    }
  }
  EXPECT_LE(worst, 1e-6);
}

TEST(Invocation, EmptyRebarGroupIsAnError)
{
  MemoryHost h;
  fill(h, 4);
  for (int &m : h.mask) m &= ~kRebar;
  try {
    run_invocation(h, parse_fix_arguments({"0", "bars"}));
    FAIL() << "no error";
  } catch (const std::runtime_error &e) {
    EXPECT_STREQ(e.what(), "Fix reinforce/invert rebar group 'bars' is empty");
  }
}

TEST(Invocation, ImpossibleRadiusRangeFromSceneIsAnError)
{
  MemoryHost h;
  h.add({0.5, 0.5, 0.5}, 0.05, kGroup | kRebar);
  h.add({0.2, 0.2, 0.2}, 0.0, kGroup);    // a matrix sphere of radius 0
  h.add({0.2, 0.5, 0.2}, 0.1, kGroup);
  EXPECT_THROW(run_invocation(h, parse_fix_arguments({"0", "bars"})), std::runtime_error);
}

// Matrix spheres that already overlap each other near a bar: the fix leaves
// them as they are, says so in the log and in f_ID[10], and makes it no
// worse (no relocated sphere overlaps anything).
TEST(Invocation, ReportsPreExistingOverlapsAndLeavesThem)
{
  MemoryHost h;
  fill(h, 5);
  // Two matrix spheres pushed into each other next to the bar.
  h.add({0.5, 0.62, 0.5}, 0.03, kGroup);
  h.add({0.5, 0.62, 0.55}, 0.03, kGroup);
  const std::array<double, 3> p1 = h.pos[h.pos.size() - 2], p2 = h.pos.back();
  const Totals t = run_invocation(h, parse_fix_arguments({"0", "bars"}));
  EXPECT_GE(t.packing_overlaps, 1);
  // The pair overlaps by 0.01 (rmin is at most 0.04): at least 0.25 rmin;
  // the two spheres may overlap lattice spheres more.
  EXPECT_GE(t.packing_max_overlap, 0.25);
  bool said = false;
  for (const std::string &line : h.logged)
    said = said || line.find("already has") != std::string::npos;
  EXPECT_TRUE(said);
  EXPECT_EQ(output_vector(t)[9], t.packing_overlaps);
  // The pair is still there, unmoved.
  int found = 0;
  for (const auto &p : h.pos) found += (p == p1) + (p == p2);
  EXPECT_EQ(found, 2);
}

// Matrix spheres of radius 0 only: an impossible radius range, not "no
// matrix" (which would silently do nothing).
TEST(Invocation, ZeroRadiusMatrixIsAnError)
{
  MemoryHost h;
  h.add({0.5, 0.5, 0.5}, 0.05, kGroup | kRebar);
  h.add({0.52, 0.5, 0.5}, 0.0, kGroup);
  EXPECT_THROW(run_invocation(h, parse_fix_arguments({"0", "bars"})), std::runtime_error);
}

// No matrix sphere at all: nothing to do, zero totals, one log line.
TEST(Invocation, NoMatrixDoesNothing)
{
  MemoryHost h;
  h.add({0.5, 0.5, 0.5}, 0.05, kGroup | kRebar);
  const Totals t = run_invocation(h, parse_fix_arguments({"0", "bars"}));
  EXPECT_EQ(t.stats.targets, 0);
  EXPECT_EQ(t.stats.solves, 0);
  EXPECT_EQ(h.logged.size(), 1u);
}

// No target anywhere: one refresh at the start and nothing per round.
TEST(Invocation, NoTargetsNoRounds)
{
  MemoryHost h;
  fill(h, 6);
  for (std::size_t i = 0; i < h.mask.size(); ++i)
    if (h.mask[i] & kRebar) h.pos[i][1] = 0.999;    // the bar along an edge, clear of the lattice
  for (std::size_t i = 0; i < h.mask.size(); ++i)
    if (h.mask[i] & kRebar) h.radius[i] = 0.001;
  const Totals t = run_invocation(h, parse_fix_arguments({"0", "bars"}));
  EXPECT_EQ(t.stats.targets, 0);
  EXPECT_EQ(t.rounds, 0);
  EXPECT_EQ(h.refreshes, 1);
}

// One matrix radius with size fit: only voids of exactly that radius fit.
// The log says so and names the keywords that change it.
TEST(Invocation, MonodisperseFitSaysSo)
{
  MemoryHost h;
  fill(h, 7);
  for (std::size_t i = 0; i < h.mask.size(); ++i)
    if (!(h.mask[i] & kRebar)) h.radius[i] = 0.03;
  run_invocation(h, parse_fix_arguments({"0", "bars", "size", "fit"}));
  bool said = false;
  for (const std::string &line : h.logged)
    said = said || (line.find("single radius") != std::string::npos &&
                    line.find("size keep") != std::string::npos);
  EXPECT_TRUE(said);
  MemoryHost k;
  fill(k, 7);
  run_invocation(k, parse_fix_arguments({"0", "bars", "size", "fit"}));    // radii spread: none
  for (const std::string &line : k.logged) EXPECT_EQ(line.find("single radius"), std::string::npos);
}

// Rebar of radius 0 is refused with one clear message (a point has no
// volume to displace).
TEST(Invocation, ZeroRadiusRebarIsAnError)
{
  MemoryHost h;
  fill(h, 8);
  h.add({0.5, 0.5, 0.5}, 0.0, kGroup | kRebar);
  try {
    run_invocation(h, parse_fix_arguments({"0", "bars"}));
    FAIL() << "no error";
  } catch (const std::runtime_error &e) {
    EXPECT_NE(std::string(e.what()).find("rebar atom"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("has radius 0"), std::string::npos);
  }
}
