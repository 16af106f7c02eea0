// The records a round's results travel as between processes.
#include "reinforce_live_view.h"
#include "reinforce_round_records.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace reinforce;

// Every kind, and IDs a double cannot hold (above 2^53, negative, the
// extremes of 64 bits), come back exactly.
TEST(RoundRecords, EncodeDecodeIsExact)
{
  const std::int64_t big = (std::int64_t{1} << 53) + 1;
  const std::vector<RoundRecord> in = {
      {1, RecordKind::Placed, {0.1, -2.5e-300, 3e300}, 0.004},
      {big, RecordKind::Deleted, {}, 0},
      {std::numeric_limits<std::int64_t>::max(), RecordKind::Kept, {}, 0},
      {std::numeric_limits<std::int64_t>::min(), RecordKind::Pushed, {1e-17, 0, -1}, 0},
      {-7, RecordKind::Placed, {1, 2, 3}, 5},
      {42, RecordKind::Moved, {0.3, 1e-300, -0.0}, 0}};
  std::vector<double> flat;
  encode_records(in, flat);
  ASSERT_EQ(flat.size(), in.size() * kRecordDoubles);
  for (double v : flat) EXPECT_TRUE(std::isfinite(v));
  std::vector<RoundRecord> out;
  ASSERT_TRUE(decode_records(flat, out));
  ASSERT_EQ(out.size(), in.size());
  for (std::size_t k = 0; k < in.size(); ++k) {
    EXPECT_EQ(out[k].id, in[k].id);
    EXPECT_EQ(out[k].kind, in[k].kind);
    EXPECT_EQ(out[k].v.x, in[k].v.x);
    EXPECT_EQ(out[k].v.y, in[k].v.y);
    EXPECT_EQ(out[k].v.z, in[k].v.z);
    EXPECT_EQ(out[k].r, in[k].r);
  }
  // An empty round is an empty buffer.
  std::vector<double> none;
  encode_records({}, none);
  EXPECT_TRUE(none.empty());
  EXPECT_TRUE(decode_records(none, out));
  EXPECT_TRUE(out.empty());
}

// A buffer that is not whole records, or has an unknown kind, is refused.
TEST(RoundRecords, MalformedBuffersAreRefused)
{
  std::vector<double> flat;
  encode_records({{3, RecordKind::Pushed, {1, 1, 1}, 0}}, flat);
  std::vector<RoundRecord> out;
  std::vector<double> short_buffer(flat.begin(), flat.end() - 1);
  EXPECT_FALSE(decode_records(short_buffer, out));
  for (double kind : {-1.0, 5.0, 1.5, static_cast<double>(NAN)}) {
    std::vector<double> bad = flat;
    bad[2] = kind;
    EXPECT_FALSE(decode_records(bad, out)) << kind;
  }
  // ID halves that are not whole numbers below 2^32.
  for (double half :
       {-1.0, 4294967296.0, 0.5, static_cast<double>(NAN), static_cast<double>(INFINITY)}) {
    std::vector<double> bad = flat;
    bad[0] = half;
    EXPECT_FALSE(decode_records(bad, out)) << half;
    bad = flat;
    bad[1] = half;
    EXPECT_FALSE(decode_records(bad, out)) << half;
  }
}

// What a relocation gives becomes one record per target, then its pushes.
TEST(RoundRecords, RecordsOfARelocation)
{
  Relocation rel;
  rel.targets.push_back({0, 10, Outcome::Placed, {1, 2, 3}, 0.5});
  rel.targets.push_back({1, 11, Outcome::Unplaced, {}, 0});
  rel.targets.push_back({2, 12, Outcome::Displaced, {}, 0});
  rel.pushes.push_back({20, {0.1, 0, 0}});
  const std::vector<RoundRecord> deleted = records_of(rel, Unplaced::Delete);
  ASSERT_EQ(deleted.size(), 4u);
  EXPECT_EQ(deleted[0].kind, RecordKind::Placed);
  EXPECT_EQ(deleted[0].r, 0.5);
  EXPECT_EQ(deleted[1].kind, RecordKind::Deleted);
  EXPECT_EQ(deleted[2].kind, RecordKind::Deleted);
  EXPECT_EQ(deleted[3].kind, RecordKind::Pushed);
  EXPECT_EQ(deleted[3].id, 20);
  const std::vector<RoundRecord> kept = records_of(rel, Unplaced::Keep);
  EXPECT_EQ(kept[1].kind, RecordKind::Kept);
  // Deferred for the regrowth: no record for the unplaced one (it stays
  // pending and vacant); the displaced one is still deleted.
  const std::vector<RoundRecord> deferred = records_of(rel, Unplaced::Defer);
  ASSERT_EQ(deferred.size(), 3u);
  EXPECT_EQ(deferred[0].id, 10);
  EXPECT_EQ(deferred[1].id, 12);
  EXPECT_EQ(deferred[1].kind, RecordKind::Deleted);
  EXPECT_EQ(deferred[2].kind, RecordKind::Pushed);
}

// A push moves the present sphere of an atom and leaves a vacant copy of
// the same atom (a target taken up again where it was) where it is; a
// placement replaces both.
TEST(LiveView, PushesMoveOnlyThePresentCopy)
{
  Domain box;
  box.lo = box.view_lo = box.sub_lo = {-1, -1, -1};
  box.hi = box.view_hi = box.sub_hi = {1, 1, 1};
  Particle vacant;
  vacant.id = 7;
  vacant.r = 0.1;
  vacant.role = Role::Target;
  Particle present = vacant;
  present.x = {0.5, 0, 0};
  present.r = 0.05;
  present.role = Role::Matrix;
  RoundsNear near(10);
  near.add_target({0, 0, 0}, 0);
  LiveView view({vacant, present}, near);
  view.apply({{7, RecordKind::Pushed, {0, 0.25, 0}, 0}}, box);
  std::vector<Particle> now;
  view.read_by(0, now);
  ASSERT_EQ(now.size(), 2u);
  EXPECT_EQ(now[0].role, Role::Target);
  EXPECT_EQ(now[0].x.y, 0);
  EXPECT_EQ(now[1].role, Role::Matrix);
  EXPECT_EQ(now[1].x.x, 0.5);
  EXPECT_EQ(now[1].x.y, 0.25);
  view.apply({{7, RecordKind::Placed, {0, -0.3, 0}, 0.1}}, box);
  view.read_by(0, now);
  ASSERT_EQ(now.size(), 1u);
  EXPECT_EQ(now[0].role, Role::Matrix);
  EXPECT_EQ(now[0].r, 0.1);
  EXPECT_EQ(now[0].x.y, -0.3);
}
