// The growth of the regrowth's zone (docs/design.md, "Regrowth"): its
// radii from a share of their own back to full size in stages, each
// relaxed (SoftRelaxation); the seeds that do not fit given up together;
// a zone that jams recognised at the stage that shows it; the exact end.
// Every decision is made from global values, so every process takes the
// same path.
#pragma once

#include "reinforce_regrowth_zone.h"
#include "reinforce_soft_relaxation.h"

#include <cstdint>
#include <unordered_map>
#include <vector>

namespace reinforce {

struct GrowthOutcome {
  bool clear = false;     // every sphere at full size, no pair overlapping beyond kClear
  bool jammed = false;    // an overlap of the matrix's own left: the zone went no further
  double scale = 0;       // the radii reached (a share of their own)
  std::int64_t given_up = 0;    // seeds given up while growing
};

class Growth {
public:
  Growth(HostHooks &host, Zone &zone, SoftRelaxation &relax, const std::vector<Seed> &seeds);

  // The zone from `start` of its radii to full size. Collective.
  GrowthOutcome run(double start);
  // Every kept seed given up, the zone back where it started (a zone that
  // did not end clear). Not collective: every process gives up the same.
  void undo(const std::vector<Seed> &seeds);

private:
  HostHooks &host_;
  Zone &zone_;
  SoftRelaxation &relax_;
  std::unordered_map<std::int64_t, const Seed *> seed_of_;
  GrowthOutcome outcome_;
  double started_ = 0, said_ = 0;    // wall time at the start and at the last progress line

  double drop_until(double worst, double above, int steps);
  bool drop_overlapped(double above);
  bool finish();
  void give_up(const std::vector<std::int64_t> &ids);
  void progress(const char *where);
};

}    // namespace reinforce
