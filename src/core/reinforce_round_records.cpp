#include "reinforce_round_records.h"

#include <cmath>

namespace reinforce {

std::vector<RoundRecord> records_of(const Relocation &rel, Unplaced unplaced)
{
  std::vector<RoundRecord> out;
  out.reserve(rel.targets.size() + rel.pushes.size());
  for (const TargetResult &t : rel.targets) {
    RecordKind kind = RecordKind::Placed;
    if (t.outcome == Outcome::Displaced) {
      kind = unplaced == Unplaced::Keep ? RecordKind::Kept : RecordKind::Deleted;
    } else if (t.outcome == Outcome::Unplaced) {
      if (unplaced == Unplaced::Defer) continue;
      kind = unplaced == Unplaced::Keep ? RecordKind::Kept : RecordKind::Deleted;
    }
    out.push_back({t.id, kind, t.x, t.r});
  }
  for (const Push &p : rel.pushes) out.push_back({p.id, RecordKind::Pushed, p.dx, 0});
  return out;
}

namespace {

bool whole_below(double v, double limit)
{
  return v >= 0 && v < limit && v == std::floor(v);
}

}    // namespace

void put_id(std::int64_t id, std::vector<double> &out)
{
  const std::uint64_t bits = static_cast<std::uint64_t>(id);
  out.push_back(static_cast<double>(bits >> 32));
  out.push_back(static_cast<double>(bits & 0xffffffffu));
}

bool read_id(const double *in, std::int64_t &id)
{
  // Each must be a whole number in its range before it is converted (a
  // conversion out of range is undefined).
  if (!whole_below(in[0], 4294967296.0) || !whole_below(in[1], 4294967296.0)) return false;
  id = static_cast<std::int64_t>(static_cast<std::uint64_t>(in[0]) << 32 |
                                 static_cast<std::uint64_t>(in[1]));
  return true;
}

void encode_records(const std::vector<RoundRecord> &records, std::vector<double> &out)
{
  for (const RoundRecord &r : records) {
    put_id(r.id, out);
    out.insert(out.end(), {static_cast<double>(static_cast<int>(r.kind)), r.v.x, r.v.y, r.v.z, r.r});
  }
}

bool decode_records(const std::vector<double> &in, std::vector<RoundRecord> &out)
{
  out.clear();
  if (in.size() % kRecordDoubles != 0) return false;
  out.reserve(in.size() / kRecordDoubles);
  for (std::size_t k = 0; k < in.size(); k += kRecordDoubles) {
    RoundRecord r;
    if (!read_id(&in[k], r.id) || !whole_below(in[k + 2], kRecordKinds)) return false;
    r.kind = static_cast<RecordKind>(static_cast<int>(in[k + 2]));
    r.v = {in[k + 3], in[k + 4], in[k + 5]};
    r.r = in[k + 6];
    out.push_back(r);
  }
  return true;
}

}    // namespace reinforce
