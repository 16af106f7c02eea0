// The shared invocation driver, on an in-memory host with one process.
#include "reinforce_invocation.h"

#include <gtest/gtest.h>

#include <cstdio>

#include <cmath>
#include <functional>
#include <memory>
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
    a.tag64 = tag.data();
    a.mask = mask.data();
    a.pending = pending.data();
    a.group_bit = kGroup;
    a.rebar_bit = kRebar;
    a.frozen_bits = frozen_bits;
    a.frozen_by = "fix other";
    return a;
  }
  void set_pending(int i, bool p) override { pending[i] = p; }
  void forward_pending() override {}
  GhostCutoff ensure_ghost_cutoff(double reach) override
  {
    cutoff_asked = reach;
    return {};
  }
  void restore_ghost_cutoff() override {}
  Domain placement_domain() override
  {
    Domain d;
    d.lo = {0, 0, 0};
    d.hi = d.view_hi = d.sub_hi = {1, 1, 1};
    d.walls = walls;
    d.region = region;
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
  void sum_and_max(std::vector<double> &, std::vector<double> &) override {}
  // One process, no ghosts: nothing to send.
  void forward(std::vector<double> &, int, bool) override {}
  std::vector<double> gather_all(const std::vector<double> &mine) override { return mine; }
  // One process: there are no others' results.
  void post_results(const std::vector<double> &, const std::vector<int> &) override {}
  std::vector<double> collect_results(const std::vector<int> &) override { return {}; }
  void finish_results() override {}
  double wall_time() override { return 0; }
  void log(const std::string &line) override { logged.push_back(line); }
  std::vector<std::string> warned;
  void warn(const std::string &message) override { warned.push_back(message); }
  int frozen_bits = 0;
  std::shared_ptr<const Boundaries> walls;
  std::function<bool(const Vec3 &, double)> region;
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

// The largest overlap (over the smaller radius) of a sphere whose mask
// `counted` accepts with any other sphere.
template <class Counted> double worst_overlap(const MemoryHost &h, Counted counted)
{
  double worst = -INFINITY;
  for (std::size_t i = 0; i < h.pos.size(); ++i) {
    if (!counted(h.mask[i])) continue;
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

double worst_matrix_overlap(const MemoryHost &h)
{
  return worst_overlap(h, [](int mask) { return !(mask & kRebar); });
}

}    // namespace

// A raised ghost cutoff is logged by the core, in one wording for both
// hosts, naming the stage that asked for it; a kept one is not logged
// (RelocatesDeletesAndReports).
TEST(Invocation, LogsARaisedGhostCutoff)
{
  struct RaisingHost : MemoryHost {
    std::vector<GhostCutoff> raises;
    GhostCutoff ensure_ghost_cutoff(double reach) override
    {
      MemoryHost::ensure_ghost_cutoff(reach);
      raises.push_back({reach / 2, reach, true});
      return raises.back();
    }
  } h;
  fill(h, 1);
  run_invocation(h, parse_fix_arguments({"0", "bars"}));
  std::vector<std::string> said;
  for (const std::string &line : h.logged)
    if (line.find("ghost cutoff") != std::string::npos) said.push_back(line);
  ASSERT_GE(h.raises.size(), 1u);
  ASSERT_EQ(said.size(), h.raises.size());
  for (std::size_t k = 0; k < said.size(); ++k) {
    char line[200];
    std::snprintf(line, sizeof line,
                  "fix reinforce/invert: ghost cutoff raised from %g to %g for the %s\n",
                  h.raises[k].before, h.raises[k].after, k == 0 ? "relocation" : "regrowth");
    EXPECT_EQ(said[k], line);
  }
  EXPECT_EQ(h.logged.front(), said.front());
}

// A stage that runs long says how far it got before each round after the
// first, at most every 5 s: here every call of the clock takes 10 s.
TEST(Invocation, LongStagesLogTheirProgress)
{
  struct SlowHost : MemoryHost {
    double clock = 0;
    double wall_time() override { return clock += 10; }
  } h;
  fill(h, 1);
  const Totals t = run_invocation(h, parse_fix_arguments({"0", "bars"}));
  ASSERT_GE(t.rounds, 3);
  int nth = 1, rounds = 0;
  std::size_t before = 0, blocks = 0, last_before = 0;
  for (const std::string &line : h.logged) {
    if (line.find("fix reinforce/invert: relocation: round") != 0) continue;
    double seconds = 0;
    ASSERT_EQ(std::sscanf(line.c_str(),
                          "fix reinforce/invert: relocation: round %d of %d begins after %lf s; "
                          "the rounds before it hold %zu of %zu blocks",
                          &nth, &rounds, &seconds, &before, &blocks),
              5)
        << line;
    EXPECT_EQ(rounds, t.rounds);
    EXPECT_GT(seconds, 0);
    EXPECT_GT(before, last_before);
    EXPECT_LT(before, blocks);
    last_before = before;
  }
  EXPECT_EQ(nth, t.rounds);    // every round after the first said so
  // A quick clock says nothing of the kind (RelocatesDeletesAndReports:
  // the schedule and summary lines only).
}

// The message of the error an invocation stops with ("" when none): the
// exact text, so that a wrong error cannot pass for the right one.
static std::string failure_of(MemoryHost &h, const std::vector<std::string> &args)
{
  try {
    run_invocation(h, parse_fix_arguments(args));
  } catch (const std::runtime_error &e) {
    return e.what();
  }
  return "";
}

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
  // The blocks: at least one per round, at most one per target.
  int blocks = 0;
  ASSERT_EQ(std::sscanf(h.logged[0].c_str(),
                        "fix reinforce/invert: schedule: %*d rounds, %*d targets in %d blocks",
                        &blocks),
            1)
      << h.logged[0];
  EXPECT_GE(blocks, t.rounds);
  EXPECT_LE(blocks, t.stats.targets);
  char schedule[200];
  std::snprintf(schedule, sizeof schedule,
                "fix reinforce/invert: schedule: %d rounds, %lld targets in %d blocks, busiest "
                "process %lld targets over the rounds, balance 1.00 over 1 processes\n",
                t.rounds, static_cast<long long>(t.stats.targets), blocks,
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
  EXPECT_LE(worst_overlap(h, [](int mask) { return mask == kGroup; }), 1e-6);
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
  EXPECT_EQ(failure_of(h, {"0", "bars"}),
            "Fix reinforce/invert: matrix atom 2 has radius 0; matrix spheres need a radius > 0");
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
  EXPECT_EQ(failure_of(h, {"0", "bars"}),
            "Fix reinforce/invert: matrix atom 2 has radius 0; matrix spheres need a radius > 0");
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
  // Said as a warning, and the summary line shows no infinite radius.
  ASSERT_EQ(h.warned.size(), 1u);
  EXPECT_EQ(h.warned[0], "Fix reinforce/invert has no matrix sphere (an atom of the fix group "
                         "outside the rebar group): nothing to relocate");
  EXPECT_EQ(h.logged[0].find("rmin inf"), std::string::npos) << h.logged[0];
  // With matrix spheres: no warning.
  MemoryHost m;
  fill(m, 3);
  run_invocation(m, parse_fix_arguments({"0", "bars"}));
  EXPECT_TRUE(m.warned.empty());
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

// Many targets without a place: the log says how many, the accepted range
// and the keywords that change it; a run that loses few says nothing more.
TEST(Invocation, ManyDeletedSaysWhy)
{
  MemoryHost h;
  fill(h, 8);
  // A radius no void of this scene reaches: no target finds a place.
  const Totals t = run_invocation(
      h, parse_fix_arguments({"0", "bars", "size", "fit", "radius", "0.3", "0.3", "regrow", "no"}));
  ASSERT_GT(t.stats.targets, 0);
  ASSERT_EQ(t.deleted, t.stats.targets);
  char expected[300];
  std::snprintf(expected, sizeof expected,
                "fix reinforce/invert: unplaced: %.0f of %lld targets (%.0f%%) were deleted: "
                "%.0f found no void with a radius in [0.3, 0.3] (in a dense packing of close "
                "radii few voids take even the smallest; the radius keyword widens the "
                "accepted range); unplaced keep leaves them in place\n",
                t.deleted, static_cast<long long>(t.stats.targets),
                100.0 * t.deleted / t.stats.targets, t.deleted);
  ASSERT_FALSE(h.logged.empty());
  EXPECT_EQ(h.logged.back(), expected);
  // Kept instead of deleted: no such line.
  MemoryHost k;
  fill(k, 8);
  run_invocation(k, parse_fix_arguments(
                        {"0", "bars", "size", "fit", "radius", "0.3", "0.3", "unplaced", "keep"}));
  for (const std::string &line : k.logged) EXPECT_EQ(line.find("unplaced:"), std::string::npos);
  // The defaults on the same scene: fewer than one in ten deleted, no line.
  MemoryHost d;
  fill(d, 8);
  const Totals td = run_invocation(d, parse_fix_arguments({"0", "bars"}));
  ASSERT_LT(td.deleted, 0.1 * td.stats.targets);
  for (const std::string &line : d.logged) EXPECT_EQ(line.find("unplaced:"), std::string::npos);
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

namespace {

// MemoryHost with a neighbour list of its own, as source-built LAMMPS has:
// build_neighbour_lists says yes when the list reaches the cutoff asked
// (`reach`), and neighbours() answers by brute force, in index order. It
// records the queries and the atoms marked as targets.
class ListHost : public MemoryHost {
public:
  double reach = INFINITY;
  double asked = 0;
  int builds = 0, queries = 0;
  std::vector<std::int64_t> marked;    // IDs of the atoms set pending, in order

  bool build_neighbour_lists(double cutoff) override
  {
    ++builds;
    asked = cutoff;
    return cutoff <= reach;
  }
  void neighbours(int local, std::vector<int> &out) override
  {
    ++queries;
    out.clear();
    for (int j = 0; j < static_cast<int>(pos.size()); ++j) {
      const double d = std::sqrt(std::pow(pos[local][0] - pos[j][0], 2) +
                                 std::pow(pos[local][1] - pos[j][1], 2) +
                                 std::pow(pos[local][2] - pos[j][2], 2));
      if (j != local && d <= asked) out.push_back(j);
    }
  }
  void set_pending(int i, bool p) override
  {
    if (p) marked.push_back(tag[i]);
    MemoryHost::set_pending(i, p);
  }
};

// A scene with atoms outside the fix group on the bar too (obstacles, never
// targets), and two spheres of the largest matrix radius (0.04) at the edge
// of matrix-rebar contact (0.04 + 0.03) with a bead: one overlaps it by
// 1e-5 (a target), one by 1e-9, less than tol * 0.03 (not a target).
void fill_with_others(MemoryHost &h, unsigned seed)
{
  fill(h, seed);
  h.add({0.25, 0.5, 0.53}, 0.02, kOther);
  h.add({0.75, 0.47, 0.5}, 0.025, kOther);
  std::vector<std::array<double, 3>> beads;
  for (std::size_t i = 0; i < h.pos.size(); ++i)
    if (h.mask[i] & kRebar) beads.push_back(h.pos[i]);
  const std::array<double, 3> b1 = beads.at(6), b2 = beads.at(12);
  h.add({b1[0], b1[1], b1[2] + (0.07 - 1e-5)}, 0.04, kGroup);
  h.add({b2[0], b2[1] - (0.07 - 1e-9), b2[2]}, 0.04, kGroup);
}

// Matrix-rebar contact: the largest matrix radius (the fix group without the
// rebar; atoms outside the group are never targets) plus the largest rebar
// radius.
double contact_of(const MemoryHost &h)
{
  double matrix = 0, rebar = 0;
  for (std::size_t i = 0; i < h.radius.size(); ++i) {
    if (h.mask[i] & kRebar)
      rebar = std::max(rebar, h.radius[i]);
    else if (h.mask[i] & kGroup)
      matrix = std::max(matrix, h.radius[i]);
  }
  return matrix + rebar;
}

void expect_same_relocation(const ListHost &a, const Totals &ta, const ListHost &b,
                            const Totals &tb)
{
  EXPECT_EQ(a.marked, b.marked);
  EXPECT_EQ(ta.stats.targets, tb.stats.targets);
  EXPECT_EQ(ta.stats.relocated, tb.stats.relocated);
  EXPECT_EQ(ta.stats.unplaced, tb.stats.unplaced);
  EXPECT_EQ(ta.stats.solves, tb.stats.solves);
  EXPECT_EQ(ta.stats.volume_before, tb.stats.volume_before);
  EXPECT_EQ(ta.stats.volume_after, tb.stats.volume_after);
  EXPECT_EQ(a.tag, b.tag);
  EXPECT_EQ(a.pos, b.pos);
  EXPECT_EQ(a.radius, b.radius);
}

}    // namespace

// The overlap check that finds the targets, answered by the
// host's list, gives the same targets as the engine's grid, and the same
// relocation; the list is asked for matrix rmax + rebar rmax.
TEST(Invocation, HostListFindsTheSameTargetsAsTheGrid)
{
  for (unsigned seed : {1u, 9u, 10u}) {
    for (const char *size : {"keep", "fit"}) {
      ListHost with_list, grid;
      fill_with_others(with_list, seed);
      fill_with_others(grid, seed);
      grid.reach = 0;    // no list: the engine's grid
      const double contact = contact_of(with_list);
      const FixOptions options = parse_fix_arguments({"0", "bars", "size", size});
      const Totals tl = run_invocation(with_list, options);
      const Totals tg = run_invocation(grid, options);
      SCOPED_TRACE(std::string("seed ") + std::to_string(seed) + " size " + size);
      EXPECT_EQ(with_list.builds, 1);
      EXPECT_EQ(with_list.asked, contact);
      EXPECT_GT(with_list.queries, 0);
      EXPECT_EQ(grid.builds, 1);
      EXPECT_EQ(grid.queries, 0);
      EXPECT_GT(tl.stats.targets, 10);
      expect_same_relocation(with_list, tl, grid, tg);
    }
  }
}

// A list shorter than matrix-rebar contact (radii grew since the host set it
// up) is not used: the grid answers, with the same result.
TEST(Invocation, ShortHostListFallsBackToTheGrid)
{
  ListHost reference, short_list;
  fill_with_others(reference, 11);
  fill_with_others(short_list, 11);
  reference.reach = 0;
  const double contact = contact_of(short_list);
  short_list.reach = std::nextafter(contact, 0.0);
  const FixOptions options = parse_fix_arguments({"0", "bars"});
  const Totals ts = run_invocation(short_list, options);
  const Totals tr = run_invocation(reference, options);
  EXPECT_EQ(short_list.asked, contact);
  EXPECT_EQ(short_list.builds, 1);
  EXPECT_EQ(short_list.queries, 0);
  EXPECT_GT(ts.stats.targets, 10);
  expect_same_relocation(short_list, ts, reference, tr);
  // Exactly long enough: used.
  ListHost exact;
  fill_with_others(exact, 11);
  exact.reach = contact;
  const Totals te = run_invocation(exact, options);
  EXPECT_GT(exact.queries, 0);
  expect_same_relocation(exact, te, reference, tr);
}

// A target with nothing around it but the bar: the log says it had no
// neighbours within search, not that the packing was dense.
TEST(Invocation, LoneTargetSaysItHadNoNeighbours)
{
  MemoryHost h;
  for (double x = 0.2; x < 0.8; x += 0.05) h.add({x, 0.5, 0.5}, 0.03, kGroup | kRebar);
  h.add({0.5, 0.53, 0.5}, 0.02, kGroup);
  const Totals t = run_invocation(h, parse_fix_arguments({"0", "bars", "regrow", "no"}));
  ASSERT_EQ(t.stats.targets, 1);
  EXPECT_EQ(t.deleted, 1);
  EXPECT_EQ(t.stats.isolated, 1);
  ASSERT_FALSE(h.logged.empty());
  EXPECT_EQ(h.logged.back(), "fix reinforce/invert: unplaced: 1 of 1 targets (100%) were deleted: "
                             "1 had fewer than four neighbours within search 0.04 (the search "
                             "keyword widens it); unplaced keep leaves them in place\n");
}

// A bar sphere larger than the box: the line says so.
TEST(Invocation, BarLargerThanTheBoxIsNamed)
{
  MemoryHost h;
  h.add({0.5, 0.5, 0.5}, 0.7, kGroup | kRebar);
  for (double x = 0.1; x < 0.95; x += 0.2)
    for (double y = 0.1; y < 0.95; y += 0.2) h.add({x, y, 0.5}, 0.05, kGroup);
  const Totals t = run_invocation(h, parse_fix_arguments({"0", "bars", "regrow", "no"}));
  ASSERT_GT(t.deleted, 0);
  ASSERT_FALSE(h.logged.empty());
  EXPECT_NE(h.logged.back().find("were deleted: a bar sphere (radius 0.7) is larger than the box"),
            std::string::npos)
      << h.logged.back();
}

namespace {

// A second bar (another reinforce/invert fix's rebar, group kOther)
// crossing the first: in the fix group `all`, overlapping the first bar.
void add_crossing_bar(MemoryHost &h)
{
  for (double y = 0.03; y < 0.97; y += 0.05) h.add({0.5, y, 0.52}, 0.03, kGroup | kOther);
}

}    // namespace

// The rebar of another reinforce/invert fix is never moved or deleted, and
// the log says how many of its atoms overlapped this fix's bars.
TEST(Invocation, OtherFixesRebarIsLeftAlone)
{
  MemoryHost h;
  fill(h, 4);
  add_crossing_bar(h);
  std::vector<std::array<double, 3>> before;
  std::vector<double> radius_before;
  for (std::size_t i = 0; i < h.pos.size(); ++i)
    if (h.mask[i] & kOther) {
      before.push_back(h.pos[i]);
      radius_before.push_back(h.radius[i]);
    }
  h.frozen_bits = kOther;
  run_invocation(h, parse_fix_arguments({"0", "bars"}));
  std::size_t k = 0;
  for (std::size_t i = 0; i < h.pos.size(); ++i)
    if (h.mask[i] & kOther) {
      ASSERT_LT(k, before.size());
      EXPECT_EQ(h.pos[i], before[k]);
      EXPECT_EQ(h.radius[i], radius_before[k]);
      ++k;
    }
  EXPECT_EQ(k, before.size());    // none deleted
  bool said = false;
  for (const std::string &line : h.logged)
    said = said || (line.rfind("fix reinforce/invert: left alone ", 0) == 0 &&
                    line.find(" atoms that overlap the bars: they are rebar of fix other\n") !=
                        std::string::npos);
  EXPECT_TRUE(said);
  // Not frozen, the same atoms are targets: the test scene exercises it.
  MemoryHost m;
  fill(m, 4);
  add_crossing_bar(m);
  run_invocation(m, parse_fix_arguments({"0", "bars"}));
  std::size_t same = 0;
  k = 0;
  for (std::size_t i = 0; i < m.pos.size(); ++i)
    if (m.mask[i] & kOther) same += k < before.size() && m.pos[i] == before[k++];
  EXPECT_LT(same, before.size());
}

namespace {

// Every sphere that moved: its centre before and after, and its radius.
struct Moved {
  Vec3 from, to;
  double r;
};
std::vector<Moved> moved_spheres(const MemoryHost &before, const MemoryHost &after)
{
  std::vector<Moved> out;
  std::size_t j = 0;
  for (std::size_t i = 0; i < before.pos.size() && j < after.pos.size(); ++i) {
    if (before.tag[i] != after.tag[j]) continue;    // deleted
    const auto &a = before.pos[i], &b = after.pos[j];
    if (a != b || before.radius[i] != after.radius[j])
      out.push_back({{a[0], a[1], a[2]}, {b[0], b[1], b[2]}, after.radius[j]});
    ++j;
  }
  return out;
}

}    // namespace

// Walls of each kind (a plane, a cylinder, a mesh of two triangles) just
// beside the bar: no moved sphere crosses one or overlaps it, with and
// without pushing; without the walls the same scene does cross them.
TEST(Invocation, MovedSpheresStayClearOfTheWalls)
{
  const double z0 = 0.47;
  std::vector<std::shared_ptr<Boundaries>> kinds(3, nullptr);
  for (auto &k : kinds) k = std::make_shared<Boundaries>();
  kinds[0]->add(Plane{{0, 0, z0}, {0, 0, 1}});
  kinds[1]->add(Cylinder{{0, 0.5, 0.56}, {1, 0, 0}, 0.09});
  kinds[2]->add(Triangle{{-1, -1, z0}, {3, -1, z0}, {-1, 3, z0}});
  kinds[2]->add(Triangle{{3, -1, z0}, {3, 3, z0}, {-1, 3, z0}});
  for (const auto &args : {std::vector<std::string>{"0", "bars"},
                           std::vector<std::string>{"0", "bars", "push", "0.01"}}) {
    for (std::size_t kind = 0; kind < kinds.size(); ++kind) {
      int crossed_without = 0;
      for (bool with_walls : {true, false}) {
        MemoryHost h;
        fill(h, 5);
        const MemoryHost before = h;
        if (with_walls) h.walls = kinds[kind];
        const Totals t = run_invocation(h, parse_fix_arguments(args));
        ASSERT_GT(t.stats.relocated, 0);
        int bad = 0;
        for (const Moved &m : moved_spheres(before, h))
          bad += !kinds[kind]->admits(m.from, m.to, m.r, 1e-6);
        if (with_walls) {
          EXPECT_EQ(bad, 0) << "kind " << kind;
          EXPECT_LE(worst_matrix_overlap(h), 1e-6);
        } else {
          crossed_without = bad;
        }
      }
      EXPECT_GT(crossed_without, 0) << "kind " << kind;
    }
  }
}

// region: the whole sphere inside, not only its centre.
TEST(Invocation, RegionHoldsWholeSpheres)
{
  const double top = 0.55;
  auto inside = [top](const Vec3 &c, double r) { return c.z + r <= top; };
  int out_without = 0;
  for (bool with_region : {true, false}) {
    MemoryHost h;
    fill(h, 6);
    const MemoryHost before = h;
    // The centre-only test the region used to be.
    h.region = with_region ? std::function<bool(const Vec3 &, double)>(inside)
                           : [top](const Vec3 &c, double) { return c.z <= top; };
    const Totals t = run_invocation(h, parse_fix_arguments({"0", "bars"}));
    ASSERT_GT(t.stats.relocated, 0);
    int out = 0;
    for (const Moved &m : moved_spheres(before, h)) out += m.to.z + m.r * (1 - 1e-6) > top;
    if (with_region) {
      EXPECT_EQ(out, 0);
    } else {
      out_without = out;
    }
  }
  EXPECT_GT(out_without, 0);
}
