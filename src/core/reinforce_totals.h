// The totals of one invocation and the one table of their fields: how
// each is combined over the processes, and where the fix's global vector
// (f_ID[1] to f_ID[28]) reports it (docs/fix_reinforce_invert.rst,
// "Output"). The reductions and the output vector read the table.
#pragma once

#include "reinforce_regrowth.h"
#include "reinforce_relocation.h"

#include <array>
#include <cstddef>

namespace reinforce {

// Totals of one invocation over all processes, as the fix reports them.
struct Totals {
  Stats stats;
  double deleted = 0, kept = 0;
  double seconds = 0;
  int rounds = 0;    // rounds of the schedule that had work
  // Matrix spheres near the bars that already overlapped each other before
  // the relocation (left as they are; reported, not hidden).
  double packing_overlaps = 0, packing_max_overlap = 0;
  RegrowthStats regrowth;
  double regrowth_seconds = 0;
  // The relocation's largest overlap alone (stats.max_overlap holds the
  // regrowth's too), over rmin.
  double relocation_max_overlap = 0;
};

// Sum or Max: each process's value, combined over the processes. Global:
// the same on every process already (computed from reduced values).
enum class Reduction { Sum, Max, Global };

struct TotalsField {
  const char *name;
  Reduction reduction;
  int output;    // its f_ID index, 0 when it is not in the vector
  double (*get)(const Totals &);
  void (*set)(Totals &, double);
};

constexpr int kOutputSize = 28;
constexpr std::size_t kTotalsFields = 38;
const std::array<TotalsField, kTotalsFields> &totals_fields();

// The fix's global vector, f_ID[1] to f_ID[27], in the order of the
// table's output indices.
std::array<double, kOutputSize> output_vector(const Totals &t);

}    // namespace reinforce
