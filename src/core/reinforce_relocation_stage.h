// Relocation as a stage of the schedule: the targets are its work, in
// passes by size class (size keep: largest first), each relocated by
// relocate_targets (docs/design.md, "Rounds").
#pragma once

#include "reinforce_relocation.h"
#include "reinforce_round_records.h"
#include "reinforce_stage.h"

namespace reinforce {

// size keep: targets split into this many classes of radius (equal widths
// of the targets' range), largest first. More classes give the largest
// targets the voids first across more of the scene, but fewer targets per
// round, and so a less even share between processes: 3 kept the quality
// scenes' shell ratios of 4 within their standard error and let the small
// beam run 1.73 times faster on 2 processes (4: 1.68; docs/design.md).
constexpr int kSizeClasses = 3;

class RelocationStage : public Stage {
public:
  // target_rmin, target_rmax: the targets' radius range over all
  // processes; read: what a round reads around a target.
  RelocationStage(const Settings &settings, const Domain &domain, Unplaced unplaced,
                  double target_rmin, double target_rmax, double read, Stats &stats);
  const char *name() const override { return "relocation"; }
  int passes() const override { return classes_; }
  int pass_of(const Particle &p) const override;
  double read_reach() const override { return read_; }
  StageResult run(const std::vector<Particle> &reads,
                  const std::function<bool(const Particle &)> &mine) override;
  // The targets this process placed shrunk across thin bars, so far.
  const std::vector<ShrunkTarget> &placed_shrunk() const { return placed_shrunk_; }

private:
  const Settings &settings_;
  const Domain &domain_;
  Unplaced unplaced_;
  int classes_;
  double target_rmax_, class_width_, read_;
  Stats &stats_;
  std::vector<ShrunkTarget> placed_shrunk_;
};

}    // namespace reinforce
