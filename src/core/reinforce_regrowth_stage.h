// Regrowth as a stage of the schedule: the targets the relocation left
// without a place are its work, one pass; the seeds of each block are
// regrown together (reinforce_regrowth.h), blocks apart from each other.
#pragma once

#include "reinforce_regrowth.h"
#include "reinforce_schedule.h"
#include "reinforce_stage.h"

namespace reinforce {

class RegrowthStage : public Stage {
public:
  // width: the zone around each seed; matrix_rmax, largest_r: the largest
  // radius of a movable sphere and of any (regrowth_reach); lattice: the schedule's blocks (a
  // block's seeds are regrown as one zone).
  RegrowthStage(const Settings &settings, const Domain &domain, const BlockLattice &lattice,
                double width, double matrix_rmax, double largest_r, RegrowthStats &stats);
  const char *name() const override { return "regrowth"; }
  int passes() const override { return 1; }
  int pass_of(const Particle &p) const override { return p.role == Role::Target ? 0 : -1; }
  double read_reach() const override { return read_; }
  StageResult run(const std::vector<Particle> &reads,
                  const std::function<bool(const Particle &)> &mine) override;

private:
  const Settings &settings_;
  const Domain &domain_;
  const BlockLattice &lattice_;
  double width_, read_;
  RegrowthStats &stats_;
};

}    // namespace reinforce
