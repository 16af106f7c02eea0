// Soft-sphere relaxation of a regrowth zone's active spheres (FIRE: the
// fast inertial relaxation engine of Bitzek et al., on a harmonic overlap
// energy of unit stiffness and mass), optionally pulled towards their
// bars. Its moves keep each sphere within its cap and refuse what the box
// faces, walls or region refuse; what it leaves is an overlap to be
// checked (or projected out) by the caller.
#pragma once

#include "reinforce_domain.h"
#include "reinforce_regrowth_zone.h"

#include <cstdint>
#include <vector>

namespace reinforce {

class SoftRelaxation {
public:
  // Over `bodies` (those `active` move; each against the bodies it can
  // touch, can_touch), inside `domain`; tol as in Settings.
  SoftRelaxation(std::vector<Body> &bodies, const std::vector<std::size_t> &active,
                 const Domain &domain, double tol);

  // The pull towards a sphere's bar, as a share of its radius times its
  // mobility (0: none).
  void set_pull(double pull) { pull_ = pull; }

  // Each pair's contact distance lengthened by `pad` of its smaller radius
  // (0: none): relaxed to overlaps below the pad, the true radii clear.
  void set_pad(double pad) { pad_ = pad; }

  // At most `iters` steps, until the largest overlap (over the smaller
  // radius) is at most `done`; adds the steps to `steps`. Returns the
  // largest overlap.
  double run(int iters, double done, std::int64_t &steps);

private:
  std::vector<Body> &bodies_;
  const std::vector<std::size_t> &active_;
  const Domain &domain_;
  double tol_;
  double pull_ = 0;
  double pad_ = 0;
  double skin_ = 0;                           // of the neighbour lists
  double largest_ = 0;                        // the largest radius of a body
  std::vector<std::vector<Contact>> near_;    // an active sphere's neighbours
  std::vector<Vec3> built_;                   // where it was when they were found

  void size_lists();
  double forces(std::vector<Vec3> &f) const;
  void build_near();
};

}    // namespace reinforce
