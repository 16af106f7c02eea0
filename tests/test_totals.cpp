// The table of the totals: every f_ID index once, each field read and
// written where the output vector and the reductions expect it.
#include "reinforce_run_stages.h"
#include "reinforce_totals.h"

#include <gtest/gtest.h>

#include <set>
#include <string>

using namespace reinforce;

TEST(Totals, EveryOutputIndexOnce)
{
  std::set<int> seen;
  std::set<std::string> names;
  for (const TotalsField &f : totals_fields()) {
    EXPECT_TRUE(names.insert(f.name).second) << f.name;
    if (f.output == 0) continue;
    EXPECT_GE(f.output, 1);
    EXPECT_LE(f.output, kOutputSize);
    EXPECT_TRUE(seen.insert(f.output).second) << f.name;
  }
  EXPECT_EQ(seen.size(), static_cast<std::size_t>(kOutputSize));
}

// Each field set to a distinct value comes back from get() and lands at its
// index of the output vector; fields never share storage.
TEST(Totals, FieldsAreDistinctAndOutputWhereTheTableSays)
{
  Totals t;
  double v = 1;
  for (const TotalsField &f : totals_fields()) f.set(t, v++);
  v = 1;
  for (const TotalsField &f : totals_fields()) EXPECT_EQ(f.get(t), v++) << f.name;
  EXPECT_EQ(t.stats.targets, 1);
  EXPECT_EQ(t.stats.relocated, 2);
  EXPECT_EQ(t.deleted, 3);
  EXPECT_EQ(t.rounds, 17);
  const auto out = output_vector(t);
  for (const TotalsField &f : totals_fields()) {
    if (f.output > 0) {
      EXPECT_EQ(out[f.output - 1], f.get(t)) << f.name;
    }
  }
  // The documented order (docs/fix_reinforce_invert.rst, "Output").
  EXPECT_EQ(out[8], t.seconds);
  EXPECT_EQ(out[9], t.packing_overlaps);
  EXPECT_EQ(out[15], static_cast<double>(t.stats.displaced));
  EXPECT_EQ(out[25], static_cast<double>(t.stats.shrunk));
  EXPECT_EQ(out[26], static_cast<double>(t.regrowth.shrunk_regrown));
  EXPECT_EQ(out[6], t.stats.max_overlap);
  EXPECT_EQ(out[19], static_cast<double>(t.regrowth.inexact));
  EXPECT_EQ(out[22], t.regrowth.max_overlap);
  EXPECT_EQ(out[27], t.relocation_max_overlap);
}

// The summary's largest overlap is the relocation's or the regrowth's,
// whichever is larger; the relocation's own is kept apart (f_ID[28]).
TEST(Totals, RegrowthFoldedIntoTheResidualOverlap)
{
  Totals t;
  t.stats.max_overlap = 1e-14;
  t.regrowth.max_overlap = 2e-13;
  t.regrowth.regrown = 3;
  t.stats.unplaced = 5;
  fold_regrowth(t);
  EXPECT_EQ(t.stats.max_overlap, 2e-13);
  EXPECT_EQ(t.relocation_max_overlap, 1e-14);
  EXPECT_EQ(t.stats.unplaced, 2);
  Totals u;
  u.stats.max_overlap = 3e-14;
  u.regrowth.max_overlap = 0;
  fold_regrowth(u);
  EXPECT_EQ(u.stats.max_overlap, 3e-14);
  EXPECT_EQ(u.relocation_max_overlap, 3e-14);
}
