// Making room for a target at its own size: the target is put at a place
// and the spheres it overlaps are pushed apart, sweep after sweep, in the
// manner of Jodrey and Tory's collective rearrangement (docs/design.md,
// "Making room").
#pragma once

#include "reinforce_domain.h"
#include "reinforce_relocation.h"
#include "reinforce_scene.h"
#include "reinforce_settings.h"

#include <cstdint>
#include <map>
#include <vector>

namespace reinforce {

// Bounds of one attempt: sweeps over the pushed spheres, spheres pushed.
constexpr int kMaxSweeps = 40;
constexpr std::size_t kMaxPushed = 48;
// The pushes go on until no pair with a moved sphere overlaps by more than
// this share of the smaller radius.
constexpr double kPushedClear = 1e-13;

class Rearrangement {
public:
  Rearrangement(Scene &scene, const Settings &s, const Domain &domain, Stats &stats);

  // Puts a sphere of the target's radius r0 (atom `id`, old centre x0) at
  // c and pushes overlapping spheres apart along their line of centres
  // until no pair involving a moved sphere overlaps by more than
  // kPushedClear of the smaller radius.
  // Rebar, atoms outside the fix group, kept targets and matrix spheres
  // farther than `zone` from the bars never move; no pushed sphere moves
  // more than `push`; the new sphere stays within r0 + search of x0; every
  // moved sphere ends admissible (box, region, walls) from where it
  // started. On success returns the new sphere's index, adds the pushes to
  // `pushes` (by atom ID) and the moved spheres to `touched`; on failure
  // puts everything back and returns -1.
  int make_room(Vec3 c, Vec3 x0, double r0, std::int64_t id, std::map<std::int64_t, Vec3> &pushes,
                std::vector<int> &touched);

private:
  Scene &scene_;
  const Settings &s_;
  const Domain &domain_;
  Stats &stats_;
  // One attempt: the new sphere, where it was put, how far from there
  // spheres may be pushed, where each moved copy started (for undo) and
  // each moved atom's displacement.
  int fresh_ = -1;
  Vec3 centre_;
  double reach_ = 0;
  std::map<int, Vec3> start_;
  std::map<std::int64_t, Vec3> moved_;

  Vec3 origin(int j) const;
  bool inside_region(Vec3 x, double r) const;
  bool movable(int j) const;
  void shift(int j, Vec3 dx);
  int undo();
  // One sweep over the spheres of `active`: each overlapping pair is pushed
  // apart (false when neither of a pair may move); the moved go to `next`.
  bool push_apart(const std::vector<int> &active, std::vector<int> &next);
  void back_into_box(const std::vector<int> &moved);
  bool within_bounds(std::int64_t id) const;
  bool accepted(Vec3 x0, double r0) const;
};

}    // namespace reinforce
