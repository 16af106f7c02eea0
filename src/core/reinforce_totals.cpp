#include "reinforce_totals.h"

#include <cstdint>

namespace reinforce {

namespace {

// A field of the totals or of their stats, as a double.
#define REINFORCE_TOTAL(member)                                                                    \
  [](const Totals &t) { return static_cast<double>(t.member); },                                   \
      [](Totals &t, double v) { t.member = static_cast<decltype(t.member)>(v); }

}    // namespace

const std::array<TotalsField, kTotalsFields> &totals_fields()
{
  static const std::array<TotalsField, kTotalsFields> fields = {{
      {"targets", Reduction::Sum, 1, REINFORCE_TOTAL(stats.targets)},
      {"relocated", Reduction::Sum, 2, REINFORCE_TOTAL(stats.relocated)},
      {"deleted", Reduction::Global, 3, REINFORCE_TOTAL(deleted)},
      {"kept", Reduction::Global, 4, REINFORCE_TOTAL(kept)},
      {"volume before", Reduction::Sum, 5, REINFORCE_TOTAL(stats.volume_before)},
      {"volume after", Reduction::Sum, 6, REINFORCE_TOTAL(stats.volume_after)},
      {"largest residual overlap / rmin", Reduction::Max, 7, REINFORCE_TOTAL(stats.max_overlap)},
      {"kernel solves", Reduction::Sum, 8, REINFORCE_TOTAL(stats.solves)},
      {"wall time", Reduction::Global, 9, REINFORCE_TOTAL(seconds)},
      {"overlapping pairs before", Reduction::Global, 10, REINFORCE_TOTAL(packing_overlaps)},
      {"largest overlap of a kept target / rmin", Reduction::Max, 11,
       REINFORCE_TOTAL(stats.max_kept_overlap)},
      {"volume removed", Reduction::Sum, 12, REINFORCE_TOTAL(stats.volume_removed)},
      {"spheres pushed", Reduction::Sum, 13, REINFORCE_TOTAL(stats.pushed)},
      {"largest push / rmin", Reduction::Max, 14, REINFORCE_TOTAL(stats.max_push)},
      {"sweeps", Reduction::Sum, 15, REINFORCE_TOTAL(stats.sweeps)},
      {"displaced by the bars", Reduction::Sum, 16, REINFORCE_TOTAL(stats.displaced)},
      {"rounds", Reduction::Global, 17, REINFORCE_TOTAL(rounds)},
      {"regrown", Reduction::Sum, 18, REINFORCE_TOTAL(regrowth.regrown)},
      {"targets deleted by the regrowth", Reduction::Sum, 19, REINFORCE_TOTAL(regrowth.deleted)},
      {"spheres the regrowth left overlapping", Reduction::Sum, 20,
       REINFORCE_TOTAL(regrowth.inexact)},
      {"moved by the regrowth", Reduction::Sum, 21, REINFORCE_TOTAL(regrowth.moved)},
      {"regrowth steps", Reduction::Global, 22, REINFORCE_TOTAL(regrowth.sweeps)},
      {"largest overlap after the regrowth / rmin", Reduction::Max, 23,
       REINFORCE_TOTAL(regrowth.max_overlap)},
      {"largest regrowth move / rmin", Reduction::Max, 24, REINFORCE_TOTAL(regrowth.max_move)},
      {"regrowth wall time", Reduction::Global, 25, REINFORCE_TOTAL(regrowth_seconds)},
      {"relocated shrunk", Reduction::Sum, 26, REINFORCE_TOTAL(stats.shrunk)},
      {"placed shrunk and regrown", Reduction::Sum, 27,
       REINFORCE_TOTAL(regrowth.shrunk_regrown)},
      {"largest overlap of the relocation / rmin", Reduction::Global, 28,
       REINFORCE_TOTAL(relocation_max_overlap)},
      {"placed shrunk and taken up", Reduction::Sum, 0, REINFORCE_TOTAL(regrowth.shrunk_seeds)},
      {"unplaced", Reduction::Sum, 0, REINFORCE_TOTAL(stats.unplaced)},
      {"unplaced with no neighbours", Reduction::Sum, 0, REINFORCE_TOTAL(stats.isolated)},
      {"largest overlap before / rmin", Reduction::Global, 0, REINFORCE_TOTAL(packing_max_overlap)},
      {"regrowth seeds", Reduction::Sum, 0, REINFORCE_TOTAL(regrowth.seeds)},
      {"regrown volume", Reduction::Sum, 0, REINFORCE_TOTAL(regrowth.volume_regrown)},
      {"displaced by the bars in the regrowth", Reduction::Sum, 0,
       REINFORCE_TOTAL(regrowth.displaced)},
      {"volume the shrunk targets got back", Reduction::Sum, 0,
       REINFORCE_TOTAL(regrowth.volume_unshrunk)},
      {"regrowth went back", Reduction::Max, 0, REINFORCE_TOTAL(regrowth.jammed)},
      {"regrowth radii reached", Reduction::Max, 0, REINFORCE_TOTAL(regrowth.jam_scale)},
  }};
  return fields;
}

#undef REINFORCE_TOTAL

std::array<double, kOutputSize> output_vector(const Totals &t)
{
  std::array<double, kOutputSize> out{};
  for (const TotalsField &f : totals_fields())
    if (f.output > 0) out[f.output - 1] = f.get(t);
  return out;
}

}    // namespace reinforce
