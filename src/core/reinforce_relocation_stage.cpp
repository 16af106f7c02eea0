#include "reinforce_relocation_stage.h"

#include <cmath>

namespace reinforce {

RelocationStage::RelocationStage(const Settings &settings, const Domain &domain, Unplaced unplaced,
                                 double target_rmin, double target_rmax, double read, Stats &stats)
    : settings_(settings), domain_(domain), unplaced_(unplaced),
      classes_(settings.size == SizeMode::Keep ? kSizeClasses : 1), target_rmax_(target_rmax),
      class_width_((target_rmax - target_rmin) / classes_), read_(read), stats_(stats)
{
}

int RelocationStage::pass_of(const Particle &p) const
{
  if (p.role != Role::Target) return -1;
  if (!(class_width_ > 0)) return 0;
  const double c = std::floor((target_rmax_ - p.r) / class_width_);
  return c < 0 ? 0 : (c >= classes_ ? classes_ - 1 : static_cast<int>(c));
}

StageResult RelocationStage::run(const std::vector<Particle> &reads,
                                 const std::function<bool(const Particle &)> &mine)
{
  const Relocation rel =
      relocate_targets(reads, settings_, domain_, unplaced_ == Unplaced::Keep, stats_, mine);
  placed_shrunk_.insert(placed_shrunk_.end(), rel.placed_shrunk.begin(),
                         rel.placed_shrunk.end());
  return {records_of(rel, unplaced_), rel.targets.size()};
}

}    // namespace reinforce
