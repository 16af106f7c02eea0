// The fix's arguments, rounds and summary line (host independent).
#include "fix_options.h"

#include <gtest/gtest.h>

#include <set>

using namespace reinforce;

namespace {

std::string error_of(const std::vector<std::string> &args)
{
  try {
    parse_fix_arguments(args);
  } catch (const OptionError &e) {
    return e.what();
  }
  return "";
}

}    // namespace

TEST(FixOptions, Defaults)
{
  const FixOptions o = parse_fix_arguments({"0", "bars"});
  EXPECT_EQ(o.every, 0);
  EXPECT_EQ(o.rebar_group, "bars");
  EXPECT_FALSE(o.radius_set);
  EXPECT_FALSE(o.search_set);
  EXPECT_EQ(o.tries, 1000);
  EXPECT_EQ(o.choice, Choice::Closest);
  EXPECT_FALSE(o.keep_unplaced);
  EXPECT_EQ(o.tol, 1e-6);
  EXPECT_EQ(o.polish, 1);
  const Settings s = make_settings(o, 0.1, 0.3);
  EXPECT_EQ(s.rmin, 0.1);
  EXPECT_EQ(s.rmax, 0.3);
  EXPECT_DOUBLE_EQ(s.search, 0.6);
}

TEST(FixOptions, AllKeywords)
{
  const FixOptions o = parse_fix_arguments({"100", "bars", "radius", "0.2", "0.4", "search", "1.5",
                                            "tries", "15", "choose", "first", "unplaced", "keep",
                                            "region", "inside", "tol", "1e-9", "polish", "0"});
  EXPECT_EQ(o.every, 100);
  EXPECT_TRUE(o.radius_set);
  EXPECT_EQ(o.rmin, 0.2);
  EXPECT_EQ(o.rmax, 0.4);
  EXPECT_EQ(o.search, 1.5);
  EXPECT_EQ(o.tries, 15);
  EXPECT_EQ(o.choice, Choice::First);
  EXPECT_TRUE(o.keep_unplaced);
  EXPECT_EQ(o.region, "inside");
  EXPECT_EQ(o.tol, 1e-9);
  EXPECT_EQ(o.polish, 0);
  const Settings s = make_settings(o, 0.01, 0.02);    // the keyword wins
  EXPECT_EQ(s.rmin, 0.2);
  EXPECT_EQ(s.rmax, 0.4);
  EXPECT_EQ(s.newton_steps, 0);
}

TEST(FixOptions, ErrorsNameTheProblem)
{
  const std::string I = "Illegal fix reinforce/invert command: ";
  EXPECT_EQ(error_of({}), I + "expected N and a rebar group ID");
  EXPECT_EQ(error_of({"0"}), I + "expected N and a rebar group ID");
  EXPECT_EQ(error_of({"-1", "bars"}), I + "N must be >= 0");
  EXPECT_EQ(error_of({"x", "bars"}), I + "expected an integer for N, got 'x'");
  EXPECT_EQ(error_of({"0", "bars", "foo", "1"}), I + "unknown keyword 'foo'");
  EXPECT_EQ(error_of({"0", "bars", "tries"}), I + "missing value for keyword 'tries'");
  EXPECT_EQ(error_of({"0", "bars", "radius", "0.1"}), I + "missing value for keyword 'radius'");
  EXPECT_EQ(error_of({"0", "bars", "radius", "0.3", "0.1"}), I + "radius rmin must be <= rmax");
  EXPECT_EQ(error_of({"0", "bars", "radius", "0", "0.1"}), I + "radius rmin must be > 0");
  EXPECT_EQ(error_of({"0", "bars", "radius", "-1", "0.1"}), I + "radius rmin must be > 0");
  EXPECT_EQ(error_of({"0", "bars", "search", "0"}), I + "search must be > 0");
  EXPECT_EQ(error_of({"0", "bars", "search", "nan"}),
            I + "expected a number for search, got 'nan'");
  EXPECT_EQ(error_of({"0", "bars", "search", "inf"}),
            I + "expected a number for search, got 'inf'");
  EXPECT_EQ(error_of({"0", "bars", "search", "1e999"}),
            I + "expected a number for search, got '1e999'");
  EXPECT_EQ(error_of({"0", "bars", "search", "2x"}), I + "expected a number for search, got '2x'");
  EXPECT_EQ(error_of({"0", "bars", "tries", "0"}), I + "tries must be > 0");
  EXPECT_EQ(error_of({"0", "bars", "tries", "1.5"}),
            I + "expected an integer for tries, got '1.5'");
  EXPECT_EQ(error_of({"0", "bars", "tries", "99999999999"}),
            I + "expected an integer for tries, got '99999999999'");
  EXPECT_EQ(error_of({"0", "bars", "choose", "best"}),
            I + "choose must be 'first' or 'closest', got 'best'");
  EXPECT_EQ(error_of({"0", "bars", "unplaced", "drop"}),
            I + "unplaced must be 'delete' or 'keep', got 'drop'");
  EXPECT_EQ(error_of({"0", "bars", "tol", "-1"}), I + "tol must be > 0");
  EXPECT_EQ(error_of({"0", "bars", "tol", "1"}), I + "tol must be < 1");
  EXPECT_EQ(error_of({"0", "bars", "polish", "11"}), I + "polish must be in 0..10");
  EXPECT_EQ(error_of({"0", "bars", "region"}), I + "missing value for keyword 'region'");
}

TEST(FixOptions, ImpossibleRadiusRangeFromScene)
{
  const FixOptions o = parse_fix_arguments({"0", "bars"});
  EXPECT_THROW(make_settings(o, 0.0, 0.0), OptionError);    // empty matrix
  EXPECT_THROW(make_settings(o, 0.3, 0.1), OptionError);
}

// No two processes of one round may be neighbours (including across a
// periodic boundary), for every grid up to 5 x 5 x 5 and every periodicity.
TEST(Rounds, NeighboursNeverShareARound)
{
  for (int px = 1; px <= 5; ++px)
    for (int py = 1; py <= 5; ++py)
      for (int pz = 1; pz <= 3; ++pz)
        for (int mask = 0; mask < 8; ++mask) {
          const int grid[3] = {px, py, pz};
          const bool periodic[3] = {(mask & 1) != 0, (mask & 2) != 0, (mask & 4) != 0};
          auto round_at = [&](int i, int j, int k) {
            const int loc[3] = {i, j, k};
            return colour_rounds(grid, loc, periodic);
          };
          std::set<int> used;
          for (int i = 0; i < px; ++i)
            for (int j = 0; j < py; ++j)
              for (int k = 0; k < pz; ++k) {
                const Rounds r = round_at(i, j, k);
                ASSERT_LT(r.mine, r.count);
                used.insert(r.mine);
                // Every neighbour in the 26-neighbourhood (with wrap where
                // periodic) that is a different process has another round.
                for (int di = -1; di <= 1; ++di)
                  for (int dj = -1; dj <= 1; ++dj)
                    for (int dk = -1; dk <= 1; ++dk) {
                      int n[3] = {i + di, j + dj, k + dk};
                      bool exists = true;
                      for (int d = 0; d < 3; ++d) {
                        if (n[d] < 0 || n[d] >= grid[d]) {
                          if (!periodic[d]) exists = false;
                          n[d] = (n[d] + grid[d]) % grid[d];
                        }
                      }
                      if (!exists || (n[0] == i && n[1] == j && n[2] == k)) continue;
                      EXPECT_NE(round_at(n[0], n[1], n[2]).mine, r.mine)
                          << px << "x" << py << "x" << pz << " periodic " << mask;
                    }
              }
          if (px * py * pz == 1) {
            EXPECT_EQ(round_at(0, 0, 0).count, 1);
          }
        }
}

TEST(Summary, ReportsCountsAndTime)
{
  Stats t;
  t.targets = 10;
  t.relocated = 8;
  t.unplaced = 2;
  t.solves = 123;
  t.max_overlap = 2.5e-13;
  EXPECT_EQ(summary_line(t, false, 0.5),
            "fix reinforce/invert: 10 targets, 8 relocated, 2 deleted, 0 kept, volume 0 -> 0, "
            "max overlap 2.50e-13 rmin, 123 solves, 0.500 s\n");
  EXPECT_NE(summary_line(t, true, 0.5).find("0 deleted, 2 kept"), std::string::npos);
}
