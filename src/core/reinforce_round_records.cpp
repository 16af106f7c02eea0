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

void encode_records(const std::vector<RoundRecord> &records, std::vector<double> &out)
{
  for (const RoundRecord &r : records) {
    const std::uint64_t bits = static_cast<std::uint64_t>(r.id);
    out.insert(out.end(),
               {static_cast<double>(bits >> 32), static_cast<double>(bits & 0xffffffffu),
                static_cast<double>(static_cast<int>(r.kind)), r.v.x, r.v.y, r.v.z, r.r});
  }
}

bool decode_records(const std::vector<double> &in, std::vector<RoundRecord> &out)
{
  out.clear();
  if (in.size() % kRecordDoubles != 0) return false;
  out.reserve(in.size() / kRecordDoubles);
  for (std::size_t k = 0; k < in.size(); k += kRecordDoubles) {
    // Each of the three must be a whole number in its range before it is
    // converted (a conversion out of range is undefined).
    auto whole_below = [](double v, double limit) {
      return v >= 0 && v < limit && v == std::floor(v);
    };
    if (!whole_below(in[k], 4294967296.0) || !whole_below(in[k + 1], 4294967296.0) ||
        !whole_below(in[k + 2], kRecordKinds))
      return false;
    const int kind = static_cast<int>(in[k + 2]);
    const std::uint64_t bits =
        static_cast<std::uint64_t>(in[k]) << 32 | static_cast<std::uint64_t>(in[k + 1]);
    RoundRecord r;
    r.id = static_cast<std::int64_t>(bits);
    r.kind = static_cast<RecordKind>(kind);
    r.v = {in[k + 3], in[k + 4], in[k + 5]};
    r.r = in[k + 6];
    out.push_back(r);
  }
  return true;
}

}    // namespace reinforce
