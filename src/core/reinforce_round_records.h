// What a round of the schedule changed, as the processes exchange it: one
// record per atom, by atom ID (docs/design.md, "Parallel rules").
#pragma once

#include "reinforce_relocation.h"

#include <cstdint>
#include <vector>

namespace reinforce {

enum class RecordKind : int {
  Placed = 0,     // v: the new centre (frame of the target's in-box copy), r: new radius
  Deleted = 1,    // no place found, deleted
  Kept = 2,       // no place found, left where it is (unplaced keep)
  Pushed = 3,     // v: the displacement of a present sphere
  Moved = 4,      // v: the new centre of a present sphere, wrapped into the box (its radius kept)
};
// The kinds above: a decoded kind is a whole number below this.
constexpr int kRecordKinds = 5;

struct RoundRecord {
  std::int64_t id = 0;
  RecordKind kind = RecordKind::Placed;
  Vec3 v;
  double r = 0;
};

// What becomes of a target the relocation found no place for: deleted,
// kept where it is (unplaced keep), or left vacant and pending for the
// regrowth (no record: its copies stay vacant in every view).
enum class Unplaced { Delete, Keep, Defer };

// The records of one relocation: its targets, then its pushes. A target
// deleted as displaced by the bars is deleted whatever `unplaced` says.
std::vector<RoundRecord> records_of(const Relocation &rel, Unplaced unplaced);

// The exchange carries doubles: a record is kRecordDoubles of them, the ID
// as two 32-bit halves (each exact in a double, so 64-bit IDs travel
// exactly), the kind as a small integer. decode_records() reads what
// encode_records() wrote, on any process; a buffer whose length is not a
// whole number of records, or with an unknown kind, is a programming error
// (decode_records returns false).
constexpr int kRecordDoubles = 7;
// An atom ID as two doubles (its 32-bit halves), and back: false when the
// two are not whole numbers below 2^32.
void put_id(std::int64_t id, std::vector<double> &out);
bool read_id(const double *in, std::int64_t &id);
void encode_records(const std::vector<RoundRecord> &records, std::vector<double> &out);
bool decode_records(const std::vector<double> &in, std::vector<RoundRecord> &out);

}    // namespace reinforce
