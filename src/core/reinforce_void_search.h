// The search for a place for one target among the voids of the scene: a
// sphere of its own radius tangent to three neighbours, or the seed
// paper's sphere tangent to four with the radius of the void
// (docs/design.md, "The relocation engine").
#pragma once

#include "reinforce_domain.h"
#include "reinforce_relocation.h"
#include "reinforce_scene.h"
#include "reinforce_settings.h"

#include <vector>

namespace reinforce {

// Rebar spheres among the candidates of one target, at most (the nearest).
constexpr int kMaxRebarCandidates = 3;
// Voids tried per target when room is made, before it counts as unplaced.
constexpr int kMaxAttempts = 2;

// Radii a search still wants: [lo, hi].
struct RadiusRange {
  double lo, hi;
};

// A place for a target: the centre of a sphere tangent to four present
// spheres that overlaps none (a void), with that sphere's radius.
struct Void {
  Vec3 c;
  double r;
  double score;    // lower is better
};

class VoidSearch {
public:
  VoidSearch(Scene &scene, const Settings &s, const Domain &domain, Stats &stats);

  // A place for a sphere of the target's own radius r0: tangent to three
  // present spheres among the candidates of its old sphere, wholly
  // admissible, overlapping nothing, its centre within r0 + search of the
  // old one; the nearest to the old centre of the first `tries` triples.
  bool own_size_void(Vec3 x0, double r0, Void &best);
  // The seed paper's placement: a tangent sphere with its radius in
  // [rmin, rmax] that overlaps nothing; first found or closest in radius.
  bool best_fit(Vec3 x0, double r0, Void &best);
  // Voids near the target, best first (at most kMaxAttempts, distinct).
  std::vector<Void> find_voids(Vec3 x0, double r0);

private:
  Scene &scene_;
  const Settings &s_;
  const Domain &domain_;
  Stats &stats_;

  template <class Range, class F>
  void for_each_solution(Vec3 x0, double r0, Range &&wanted, F &&take);
  bool overlaps_one_of(const std::vector<Candidate> &near, Vec3 c, double r,
                       double slack = 0) const;
};

}    // namespace reinforce
