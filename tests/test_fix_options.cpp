// The fix's arguments, rounds and summary line (host independent).
#include "reinforce_fix_options.h"
#include "reinforce_schedule.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
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
  EXPECT_EQ(o.size, SizeMode::Keep);
  EXPECT_FALSE(o.displaced_set);
  EXPECT_FALSE(o.walls_ignore);    // the host's walls are checked
  const Settings s = make_settings(o, 0.1, 0.3, 100);
  EXPECT_EQ(s.rmin, 0.1);
  EXPECT_EQ(s.rmax, 0.3);
  EXPECT_DOUBLE_EQ(s.search, 0.6);
  EXPECT_DOUBLE_EQ(s.zone, 0.9);
  EXPECT_EQ(s.push, 0);    // no pushing unless asked
  EXPECT_EQ(s.size, SizeMode::Keep);
  EXPECT_GT(s.displaced, 1);    // every target is tried
  EXPECT_GT(
      make_settings(parse_fix_arguments({"0", "bars", "size", "fit"}), 0.1, 0.3, 100).displaced, 1);
  EXPECT_EQ(make_settings(parse_fix_arguments({"0", "bars", "displaced", "0.5"}), 0.1, 0.3, 100)
                .displaced,
            0.5);
  EXPECT_DOUBLE_EQ(
      make_settings(parse_fix_arguments({"0", "bars", "push", "0.1"}), 0.1, 0.3, 100).push, 0.1);
}

// Gaps, pushes and radii larger than the box are capped at its diagonal, so
// the reach (and the ghost cutoff) stays finite.
TEST(FixOptions, HugeValuesAreCappedByTheBox)
{
  const FixOptions o = parse_fix_arguments({"0", "bars", "radius", "0.004", "1e308", "search",
                                            "1e300", "zone", "1e300", "push", "1e300"});
  const Settings s = make_settings(o, 0.004, 0.008, 0.5);
  EXPECT_EQ(s.rmax, 0.5);
  EXPECT_EQ(s.search, 0.5);
  EXPECT_EQ(s.zone, 0.5);
  EXPECT_EQ(s.push, 0.5);
  const Footprint f = footprint(s, 0.008, 0.5);
  EXPECT_TRUE(std::isfinite(f.read));
}

TEST(FixOptions, UnplacedKeepTriesEveryTarget)
{
  const Settings s =
      make_settings(parse_fix_arguments({"0", "bars", "unplaced", "keep"}), 1, 2, 100);
  EXPECT_GT(s.displaced, 1);
}

TEST(FixOptions, AllKeywords)
{
  const FixOptions o = parse_fix_arguments(
      {"100",    "bars",  "radius",   "0.2",  "0.4",    "search", "1.5",  "tries",     "15",
       "choose", "first", "unplaced", "keep", "region", "inside", "tol",  "1e-9",      "polish",
       "0",      "size",  "fit",      "zone", "0.7",    "push",   "0.05", "displaced", "0.8"});
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
  EXPECT_EQ(o.size, SizeMode::Fit);
  EXPECT_EQ(o.zone, 0.7);
  EXPECT_EQ(o.push, 0.05);
  EXPECT_EQ(o.displaced, 0.8);
  const Settings s = make_settings(o, 0.01, 0.02, 100);    // the keyword wins
  EXPECT_EQ(s.rmin, 0.2);
  EXPECT_EQ(s.rmax, 0.4);
  EXPECT_EQ(s.newton_steps, 0);
  EXPECT_EQ(s.zone, 0.7);
  EXPECT_EQ(s.push, 0.05);
  EXPECT_EQ(parse_fix_arguments({"0", "bars", "displaced", "none"}).displaced, 2);
}

// Every ERROR text of the parser, from one table: the arguments after
// "fix ID group-ID reinforce/invert" and the whole message. The hosts'
// input-script tests check only that such a message reaches their ERROR
// line (lammps_error_parser_*, liggghts_error_parser_*).
struct ParserCase {
  std::vector<std::string> args;
  const char *message;    // after "Illegal fix reinforce/invert command: "
};

const ParserCase kParserCases[] = {
    {{}, "expected N and a rebar group ID"},
    {{"0"}, "expected N and a rebar group ID"},
    {{"-1", "bars"}, "N must be >= 0"},
    {{"x", "bars"}, "expected an integer for N, got 'x'"},
    {{"0", "bars", "foo", "1"}, "unknown keyword 'foo'"},
    {{"0", "bars", "tries"}, "missing value for keyword 'tries'"},
    {{"0", "bars", "radius", "0.1"}, "missing value for keyword 'radius'"},
    {{"0", "bars", "radius", "0.3", "0.1"}, "radius rmin must be <= rmax"},
    {{"0", "bars", "radius", "0", "0.1"}, "radius rmin must be > 0"},
    {{"0", "bars", "radius", "-1", "0.1"}, "radius rmin must be > 0"},
    {{"0", "bars", "search", "0"}, "search must be > 0"},
    {{"0", "bars", "search", "nan"}, "expected a number for search, got 'nan'"},
    {{"0", "bars", "search", "inf"}, "expected a number for search, got 'inf'"},
    {{"0", "bars", "search", "1e999"}, "expected a number for search, got '1e999'"},
    {{"0", "bars", "search", "2x"}, "expected a number for search, got '2x'"},
    {{"0", "bars", "tries", "0"}, "tries must be > 0"},
    {{"0", "bars", "tries", "1.5"}, "expected an integer for tries, got '1.5'"},
    {{"0", "bars", "tries", "99999999999"}, "expected an integer for tries, got '99999999999'"},
    {{"0", "bars", "choose", "best"}, "choose must be 'first' or 'closest', got 'best'"},
    {{"0", "bars", "unplaced", "drop"}, "unplaced must be 'delete' or 'keep', got 'drop'"},
    {{"0", "bars", "tol", "-1"}, "tol must be in [1e-10, 1)"},
    {{"0", "bars", "tol", "1"}, "tol must be in [1e-10, 1)"},
    {{"0", "bars", "tol", "1e-14"}, "tol must be in [1e-10, 1)"},
    {{"0", "bars", "tol", "4.9e-324"}, "expected a number for tol, got '4.9e-324'"},
    {{"0", "bars", "size", "big"}, "size must be 'keep' or 'fit', got 'big'"},
    {{"0", "bars", "zone", "-1"}, "zone must be >= 0"},
    {{"0", "bars", "push", "nan"}, "expected a number for push, got 'nan'"},
    {{"0", "bars", "displaced", "0"}, "displaced must be in (0, 1] or 'none'"},
    {{"0", "bars", "displaced", "1.5"}, "displaced must be in (0, 1] or 'none'"},
    {{"0", "bars", "polish", "11"}, "polish must be in 0..10"},
    {{"0", "bars", "region"}, "missing value for keyword 'region'"},
    {{"0", "bars", "Radius", "0.01", "0.02"}, "unknown keyword 'Radius'"},
    {{"0", "bars", "radius", "0.05", "0.05", "0.1"}, "unknown keyword '0.1'"},
    {{"0", "bars", "choose"}, "missing value for keyword 'choose'"},
    {{"0", "bars", "unplaced"}, "missing value for keyword 'unplaced'"},
    {{"0", "bars", "radius", "0.1", "-2"}, "radius rmax must be > 0"},
    {{"0", "bars", "radius", "nan", "0.1"}, "expected a number for radius rmin, got 'nan'"},
    {{"0", "bars", "radius", "0.1", "inf"}, "expected a number for radius rmax, got 'inf'"},
    {{"0", "bars", "search", "-1"}, "search must be > 0"},
    {{"0", "bars", "search", "1e400"}, "expected a number for search, got '1e400'"},
    {{"0", "bars", "tries", "-3"}, "tries must be > 0"},
    {{"0", "bars", "tol", "0"}, "tol must be in [1e-10, 1)"},
    {{"0", "bars", "tol", "-1e-6"}, "tol must be in [1e-10, 1)"},
    {{"0", "bars", "tol", "1e-15"}, "tol must be in [1e-10, 1)"},
    {{"0", "bars", "push", "inf"}, "expected a number for push, got 'inf'"},
    {{"0", "bars", "displaced", "2"}, "displaced must be in (0, 1] or 'none'"},
    {{"0", "bars", "tol", "nan"}, "expected a number for tol, got 'nan'"},
    {{"0", "bars", "tol", "inf"}, "expected a number for tol, got 'inf'"},
    {{"0", "bars", "polish", "-1"}, "polish must be in 0..10"},
    {{"0", "bars", "polish", "0.5"}, "expected an integer for polish, got '0.5'"},
    {{"1.5", "bars"}, "expected an integer for N, got '1.5'"},
    {{"99999999999", "bars"}, "expected an integer for N, got '99999999999'"},
    {{"0", "bars", "radius", "-0.1", "0.1"}, "radius rmin must be > 0"},
    {{"0", "bars", "tol", "1e-13"}, "tol must be in [1e-10, 1)"},
};

TEST(FixOptions, EveryParserErrorText)
{
  const std::string I = "Illegal fix reinforce/invert command: ";
  for (const ParserCase &c : kParserCases) {
    std::string command;
    for (const std::string &w : c.args) command += " " + w;
    EXPECT_EQ(error_of(c.args), I + c.message) << "arguments:" << command;
  }
}

// walls check|ignore: whether the host's wall fixes are read (check, the
// default) or not (ignore); the last one given wins, in any place among the
// other keywords, which it leaves as they were.
TEST(FixOptions, WallsCheckOrIgnore)
{
  EXPECT_FALSE(parse_fix_arguments({"0", "bars", "walls", "check"}).walls_ignore);
  EXPECT_TRUE(parse_fix_arguments({"0", "bars", "walls", "ignore"}).walls_ignore);
  EXPECT_FALSE(
      parse_fix_arguments({"0", "bars", "walls", "ignore", "walls", "check"}).walls_ignore);
  EXPECT_TRUE(parse_fix_arguments({"0", "bars", "walls", "check", "walls", "ignore"}).walls_ignore);
  const FixOptions o = parse_fix_arguments(
      {"5", "bars", "tol", "1e-9", "walls", "ignore", "unplaced", "keep", "radius", "0.2", "0.4"});
  EXPECT_TRUE(o.walls_ignore);
  EXPECT_EQ(o.every, 5);
  EXPECT_EQ(o.tol, 1e-9);
  EXPECT_TRUE(o.keep_unplaced);
  EXPECT_TRUE(o.radius_set);
  EXPECT_EQ(o.rmin, 0.2);
  EXPECT_EQ(o.rmax, 0.4);
  EXPECT_TRUE(
      parse_fix_arguments({"0", "bars", "region", "inside", "walls", "ignore"}).walls_ignore);
  EXPECT_EQ(parse_fix_arguments({"0", "bars", "region", "inside", "walls", "ignore"}).region,
            "inside");
  // The engine's settings do not depend on it.
  const Settings a = make_settings(parse_fix_arguments({"0", "bars"}), 0.1, 0.3, 100);
  const Settings b =
      make_settings(parse_fix_arguments({"0", "bars", "walls", "ignore"}), 0.1, 0.3, 100);
  EXPECT_EQ(a.rmin, b.rmin);
  EXPECT_EQ(a.rmax, b.rmax);
  EXPECT_EQ(a.search, b.search);
  EXPECT_EQ(a.zone, b.zone);
  EXPECT_EQ(a.tol, b.tol);
}

TEST(FixOptions, WallsErrorsNameTheProblem)
{
  const std::string I = "Illegal fix reinforce/invert command: ";
  EXPECT_EQ(error_of({"0", "bars", "walls"}), I + "missing value for keyword 'walls'");
  EXPECT_EQ(error_of({"0", "bars", "walls", "ignore", "walls"}),
            I + "missing value for keyword 'walls'");
  EXPECT_EQ(error_of({"0", "bars", "walls", "off"}),
            I + "walls must be 'check' or 'ignore', got 'off'");
  EXPECT_EQ(error_of({"0", "bars", "walls", "Ignore"}),    // case matters
            I + "walls must be 'check' or 'ignore', got 'Ignore'");
  EXPECT_EQ(error_of({"0", "bars", "walls", "CHECK"}),
            I + "walls must be 'check' or 'ignore', got 'CHECK'");
  EXPECT_EQ(error_of({"0", "bars", "walls", ""}), I + "walls must be 'check' or 'ignore', got ''");
  EXPECT_EQ(error_of({"0", "bars", "walls", "ignore "}),
            I + "walls must be 'check' or 'ignore', got 'ignore '");
  EXPECT_EQ(error_of({"0", "bars", "walls", "1"}),
            I + "walls must be 'check' or 'ignore', got '1'");
  // A keyword where the value should be is not taken as one.
  EXPECT_EQ(error_of({"0", "bars", "walls", "tol", "1e-6"}),
            I + "walls must be 'check' or 'ignore', got 'tol'");
  // The keyword itself is not a value of another keyword.
  EXPECT_EQ(error_of({"0", "bars", "region", "walls", "ignore"}), I + "unknown keyword 'ignore'");
  EXPECT_EQ(error_of({"0", "bars", "Walls", "ignore"}), I + "unknown keyword 'Walls'");
  EXPECT_EQ(error_of({"0", "bars", "wall", "ignore"}), I + "unknown keyword 'wall'");
  // An error after it is still reported.
  EXPECT_EQ(error_of({"0", "bars", "walls", "ignore", "tries", "0"}), I + "tries must be > 0");
  EXPECT_EQ(error_of({"0", "bars", "walls", "maybe"}),
            I + "walls must be 'check' or 'ignore', got 'maybe'");
}

// regrow: on by default with size keep (a zone 8 matrix radii wide, as
// the doc page says), not with size fit or unplaced keep unless asked (an
// error with unplaced keep); yes gives the same, a length sets the zone's
// width (capped by the box); no turns it off.
TEST(FixOptions, RegrowWidthOrNo)
{
  EXPECT_DOUBLE_EQ(make_settings(parse_fix_arguments({"0", "bars"}), 0.1, 0.3, 100).regrow,
                   8 * 0.3);
  EXPECT_EQ(
      make_settings(parse_fix_arguments({"0", "bars", "unplaced", "keep"}), 0.1, 0.3, 100).regrow,
      0);
  EXPECT_EQ(make_settings(parse_fix_arguments({"0", "bars", "regrow", "no"}), 0.1, 0.3, 100).regrow,
            0);
  EXPECT_EQ(make_settings(parse_fix_arguments({"0", "bars", "size", "fit"}), 0.1, 0.3, 100).regrow,
            0);    // the seed paper's mode, unless asked
  EXPECT_DOUBLE_EQ(
      make_settings(parse_fix_arguments({"0", "bars", "regrow", "yes"}), 0.1, 0.3, 100).regrow,
      8 * 0.3);
  EXPECT_EQ(
      make_settings(parse_fix_arguments({"0", "bars", "regrow", "0.5"}), 0.1, 0.3, 100).regrow,
      0.5);
  EXPECT_EQ(
      make_settings(parse_fix_arguments({"0", "bars", "regrow", "1e30"}), 0.1, 0.3, 100).regrow,
      100);
  EXPECT_EQ(make_settings(parse_fix_arguments({"0", "bars", "regrow", "0.5", "regrow", "no"}), 0.1,
                          0.3, 100)
                .regrow,
            0);
  // size fit does not turn it off.
  EXPECT_EQ(make_settings(parse_fix_arguments({"0", "bars", "size", "fit", "regrow", "0.5"}), 0.1,
                          0.3, 100)
                .regrow,
            0.5);
  const std::string I = "Illegal fix reinforce/invert command: ";
  EXPECT_EQ(error_of({"0", "bars", "regrow", "0"}), I + "regrow must be > 0, 'yes' or 'no'");
  EXPECT_EQ(error_of({"0", "bars", "regrow", "-1"}), I + "regrow must be > 0, 'yes' or 'no'");
  EXPECT_EQ(error_of({"0", "bars", "regrow", "maybe"}),
            I + "expected a number for regrow, got 'maybe'");
  EXPECT_EQ(error_of({"0", "bars", "regrow", "inf"}),
            I + "expected a number for regrow, got 'inf'");
  EXPECT_EQ(error_of({"0", "bars", "regrow"}), I + "missing value for keyword 'regrow'");
  EXPECT_EQ(error_of({"0", "bars", "regrow", "yes", "unplaced", "keep"}),
            I + "regrow makes room for the targets unplaced keep leaves where they are: use one "
                "of them");
  EXPECT_NO_THROW(parse_fix_arguments({"0", "bars", "regrow", "no", "unplaced", "keep"}));
}

// grow: balance, the only mode, changes nothing; the retired modes are an
// ERROR that names the default; an error where there is no regrowth.
TEST(FixOptions, GrowBalanceOnly)
{
  EXPECT_DOUBLE_EQ(
      make_settings(parse_fix_arguments({"0", "bars", "grow", "balance"}), 0.1, 0.3, 100).regrow,
      8 * 0.3);
  EXPECT_DOUBLE_EQ(
      make_settings(parse_fix_arguments({"0", "bars", "grow", "balance", "regrow", "0.5"}), 0.1,
                    0.3, 100)
          .regrow,
      0.5);
  const std::string I = "Illegal fix reinforce/invert command: ";
  for (const char *retired : {"together", "each"})
    EXPECT_EQ(error_of({"0", "bars", "grow", retired}),
              I + "grow " + retired +
                  " is retired: the regrowth rebuilds one zone around every target without a "
                  "void (grow balance, the default)");
  EXPECT_EQ(error_of({"0", "bars", "grow", "both"}), I + "grow must be 'balance', got 'both'");
  EXPECT_EQ(error_of({"0", "bars", "grow"}), I + "missing value for keyword 'grow'");
  const std::string off = I + "grow sets how the regrowth grows its seeds, and the regrowth is "
                              "off (regrow no, unplaced keep, or size fit without regrow)";
  EXPECT_EQ(error_of({"0", "bars", "regrow", "no", "grow", "balance"}), off);
  EXPECT_EQ(error_of({"0", "bars", "unplaced", "keep", "grow", "balance"}), off);
  EXPECT_EQ(error_of({"0", "bars", "size", "fit", "grow", "balance"}), off);
}

TEST(FixOptions, ImpossibleRadiusRangeFromScene)
{
  const FixOptions o = parse_fix_arguments({"0", "bars"});
  const auto settings_error = [&o](double rmin, double rmax) -> std::string {
    try {
      make_settings(o, rmin, rmax, 1);
    } catch (const OptionError &e) {
      return e.what();
    }
    return "";
  };
  EXPECT_EQ(settings_error(0.0, 0.0),
            "Fix reinforce/invert: impossible radius range [0, 0]");    // empty matrix
  EXPECT_EQ(settings_error(0.3, 0.1), "Fix reinforce/invert: impossible radius range [0.3, 0.1]");
}

// Blocks of one colour never touch (including across a periodic
// boundary): two blocks of one colour are at least one block apart in some
// dimension, so relocations in them cannot reach each other when blocks are
// at least one footprint wide. Checked for many box shapes and widths.
TEST(Schedule, SameColourBlocksAreSeparated)
{
  for (double length : {0.3, 1.0, 2.5, 7.0})
    for (double width : {0.1, 0.3, 0.45, 1.1, 5.0})
      for (int mask = 0; mask < 8; ++mask) {
        const bool periodic[3] = {(mask & 1) != 0, (mask & 2) != 0, (mask & 4) != 0};
        const Vec3 lo{-1, 0, 2}, hi{-1 + length, 0.5 * length, 2 + 1.5 * length};
        const BlockLattice l = make_block_lattice(lo, hi, periodic, width);
        for (int d = 0; d < 3; ++d) {
          EXPECT_GE(l.count[d], 1);
          if (l.count[d] > 1) {
            EXPECT_GE(l.width[d], width * (1 - 1e-12));
          }
          EXPECT_NEAR(l.count[d] * l.width[d], hi[d] - lo[d], 1e-12);
          if (periodic[d] && l.count[d] > 1) {
            EXPECT_EQ(l.count[d] % 2, 0);
          }
        }
        EXPECT_LE(l.rounds(), 8);
        // Every pair of blocks of one colour: separated in some dimension.
        std::vector<std::array<int, 3>> blocks;
        for (int i = 0; i < l.count[0]; ++i)
          for (int j = 0; j < l.count[1]; ++j)
            for (int k = 0; k < l.count[2]; ++k) blocks.push_back({i, j, k});
        if (blocks.size() > 300) continue;
        auto centre = [&](const std::array<int, 3> &b) {
          Vec3 c;
          for (int d = 0; d < 3; ++d) c[d] = lo[d] + (b[d] + 0.5) * l.width[d];
          return c;
        };
        for (std::size_t p = 0; p < blocks.size(); ++p)
          for (std::size_t q = p + 1; q < blocks.size(); ++q) {
            if (l.colour_of(centre(blocks[p])) != l.colour_of(centre(blocks[q]))) continue;
            bool apart = false;
            for (int d = 0; d < 3; ++d) {
              int gap = std::abs(blocks[p][d] - blocks[q][d]);
              if (periodic[d]) gap = std::min(gap, l.count[d] - gap);
              apart = apart || gap >= 2;
            }
            EXPECT_TRUE(apart) << "length " << length << " width " << width << " mask " << mask;
          }
      }
}

// Points map to the block that holds them; points on or past the box edges
// are clamped to the edge blocks.
TEST(Schedule, PointsFallInTheirBlock)
{
  const bool periodic[3] = {false, true, false};
  const BlockLattice l = make_block_lattice({0, 0, 0}, {1, 1, 1}, periodic, 0.3);
  EXPECT_EQ(l.count[0], 3);
  EXPECT_EQ(l.count[1], 2);    // 3 would break the parity across the periodic boundary
  int b[3];
  l.block_of({0.999999, 0.5, 1.0}, b);
  EXPECT_EQ(b[0], 2);
  EXPECT_EQ(b[1], 1);
  EXPECT_EQ(b[2], 2);
  l.block_of({-0.1, -1e-300, 1.7}, b);
  EXPECT_EQ(b[0], 0);
  EXPECT_EQ(b[1], 0);
  EXPECT_EQ(b[2], 2);
  const Vec3 c = l.centre_of({0.5, 0.2, 0.1});
  EXPECT_DOUBLE_EQ(c.x, 0.5);
  EXPECT_DOUBLE_EQ(c.y, 0.25);
  EXPECT_DOUBLE_EQ(c.z, 1.0 / 6);
}

// reach_beyond: every block whose centre lies in a subdomain stays within
// that reach of it (the owner of the centre sees the whole block through
// its ghosts), never more than half a block; 0 where the subdomain's faces
// lie on block faces, and for a subdomain that holds no block centre.
TEST(Schedule, ReachBeyondCoversTheBlocksOfASubdomain)
{
  const bool periodic[3] = {false, true, false};
  const Vec3 lo{-1, 0, 2}, hi{1, 0.5, 3};
  const BlockLattice l = make_block_lattice(lo, hi, periodic, 0.12);
  const double half = 0.5 * std::max({l.width[0], l.width[1], l.width[2]});
  std::mt19937_64 rng(7);
  for (int trial = 0; trial < 500; ++trial) {
    Vec3 sub_lo, sub_hi;
    for (int d = 0; d < 3; ++d) {
      std::uniform_real_distribution<double> u(lo[d], hi[d]);
      const double a = u(rng), b = u(rng);
      sub_lo[d] = trial % 5 == 0 ? lo[d] : std::min(a, b);
      sub_hi[d] = trial % 5 == 0 ? hi[d] : std::max(a, b);
    }
    const double reach = l.reach_beyond(sub_lo, sub_hi);
    EXPECT_TRUE(std::isfinite(reach));
    EXPECT_GE(reach, 0);
    EXPECT_LE(reach, half * (1 + 1e-12));
    for (int i = 0; i < l.count[0]; ++i)
      for (int j = 0; j < l.count[1]; ++j)
        for (int k = 0; k < l.count[2]; ++k) {
          const int b[3] = {i, j, k};
          bool owned = true;
          for (int d = 0; d < 3; ++d) {
            const double c = lo[d] + (b[d] + 0.5) * l.width[d];
            owned = owned && c >= sub_lo[d] && c < sub_hi[d];
          }
          if (!owned) continue;
          for (int d = 0; d < 3; ++d) {
            EXPECT_GE(lo[d] + b[d] * l.width[d], sub_lo[d] - reach - 1e-12);
            EXPECT_LE(lo[d] + (b[d] + 1) * l.width[d], sub_hi[d] + reach + 1e-12);
          }
        }
  }
  // Faces on block faces: the blocks stay inside.
  const Vec3 aligned_lo{lo.x + 2 * l.width[0], lo.y, lo.z + l.width[2]};
  const Vec3 aligned_hi{lo.x + 5 * l.width[0], hi.y, lo.z + 3 * l.width[2]};
  EXPECT_NEAR(l.reach_beyond(aligned_lo, aligned_hi), 0, 1e-12);
  // A slice thinner than a block, between two centres: no block is its.
  const Vec3 thin_lo{lo.x + 0.55 * l.width[0], lo.y, lo.z};
  const Vec3 thin_hi{lo.x + 0.95 * l.width[0], hi.y, hi.z};
  EXPECT_EQ(l.reach_beyond(thin_lo, thin_hi), 0);
  // Off the lattice by a quarter block: a quarter block beyond.
  const Vec3 off_lo{lo.x + 0.25 * l.width[0], lo.y, lo.z};
  const Vec3 off_hi{lo.x + 2.25 * l.width[0], hi.y, hi.z};
  EXPECT_NEAR(l.reach_beyond(off_lo, off_hi), 0.25 * l.width[0], 1e-12);
}

TEST(Summary, ReportsCountsAndTime)
{
  Stats t;
  t.targets = 10;
  t.relocated = 8;
  t.unplaced = 2;
  t.solves = 123;
  t.max_overlap = 2.5e-13;
  t.displaced = 1;
  t.pushed = 40;
  t.max_push = 0.25;
  t.sweeps = 300;
  EXPECT_EQ(summary_line(t, false, 0.5, 3, 0.004),
            "fix reinforce/invert: 10 targets, 8 relocated, 2 deleted (1 displaced by the bars), "
            "0 kept, volume 0 -> 0, max overlap 2.50e-13 rmin, 123 solves, 40 pushed (largest "
            "0.25 rmin, 300 sweeps), 3 rounds, 0.500 s (rmin 0.004)\n");
  EXPECT_NE(summary_line(t, true, 0.5, 3, 1).find("0 deleted"), std::string::npos);
  EXPECT_NE(summary_line(t, true, 0.5, 3, 1).find("2 kept"), std::string::npos);
}

// The WARNING on matrix lost by the regrowth: targets left shrunk, or
// deleted beyond those whose centre lies inside the bars, the share of
// their volume the targets keep, and a jam; none otherwise.
TEST(FixOptions, LostMatrixWarning)
{
  Stats s;    // 3 deleted, all 3 centred inside the bars
  s.unplaced = s.displaced = 3;
  s.volume_before = 8;
  s.volume_after = 6;
  EXPECT_EQ(lost_matrix_warning(s, false), "");
  s.shrunk = 2;
  EXPECT_EQ(lost_matrix_warning(s, false), "Fix reinforce/invert regrowth left 2 targets smaller than "
                                    "their own radius: the targets keep 0.75 of their volume");
  s.displaced = 1;
  EXPECT_EQ(lost_matrix_warning(s, false),
            "Fix reinforce/invert regrowth left 2 targets smaller than their own radius and "
            "deleted 2 targets beyond the 1 whose centre lies inside the bars: the targets keep "
            "0.75 of their volume");
  s.shrunk = 0;
  EXPECT_EQ(lost_matrix_warning(s, false),
            "Fix reinforce/invert regrowth deleted 2 targets beyond the 1 whose centre lies "
            "inside the bars: the targets keep 0.75 of their volume");
  // A zone that jammed says so, and that it went back.
  EXPECT_EQ(lost_matrix_warning(s, true),
            "Fix reinforce/invert regrowth deleted 2 targets beyond the 1 whose centre lies "
            "inside the bars: the targets keep 0.75 of their volume; its zone jammed (shrunk and "
            "grown back, the matrix did not reach its density again) and went back to the "
            "relocation's scene");
  // On only with the regrowth.
  EXPECT_TRUE(regrowth_on(parse_fix_arguments({"0", "bars"})));
  EXPECT_FALSE(regrowth_on(parse_fix_arguments({"0", "bars", "regrow", "no"})));
  EXPECT_FALSE(regrowth_on(parse_fix_arguments({"0", "bars", "size", "fit"})));
  EXPECT_TRUE(regrowth_on(parse_fix_arguments({"0", "bars", "size", "fit", "regrow", "yes"})));
  EXPECT_FALSE(regrowth_on(parse_fix_arguments({"0", "bars", "unplaced", "keep"})));
}
