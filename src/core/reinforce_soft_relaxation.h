// Soft-sphere relaxation of the regrowth's zone (FIRE: the fast inertial
// relaxation engine of Bitzek et al., on a harmonic overlap energy of unit
// stiffness and mass), every process moving its own zone spheres at once
// (docs/design.md, "Regrowth"). The same for any process count: each
// sphere's force is summed over its neighbours in (id, place) order, the
// global sums FIRE needs are exact (ExactSum), its other decisions come
// from maxima. A move keeps a sphere within its cap and refuses what the
// box faces, walls or region refuse.
#pragma once

#include "reinforce_domain.h"
#include "reinforce_host_hooks.h"
#include "reinforce_regrowth_zone.h"

#include <cstdint>
#include <vector>

namespace reinforce {

// The overlap of spheres (xi, ri) and (xj, rj) beyond `allowed`: the one
// pair test of the regrowth (positive: they overlap).
inline double pair_overlap(Vec3 xi, double ri, Vec3 xj, double rj, double allowed)
{
  return ri + rj - allowed - norm(xi - xj);
}

class SoftRelaxation {
public:
  // Over the zone's bodies (its owned movable ones move); rmin, rmax: the
  // matrix's radius range (the unit of overlaps and the lists' skin).
  SoftRelaxation(HostHooks &host, Zone &zone, const Domain &domain, double tol, double rmin,
                 double rmax);

  // The movable spheres' radii as a share of their own.
  void set_scale(double scale)
  {
    scale_ = scale;
    stale_radii_ = true;
  }
  // The pull towards a matrix sphere's bar, as a share of its radius times
  // its mobility (0: none).
  void set_pull(double pull) { pull_ = pull; }
  // Each pair of movable spheres' contact distance lengthened by `pad` of
  // its smaller radius (0: none).
  void set_pad(double pad) { pad_ = pad; }
  // The bodies' flags changed (a seed given up): the lists are made again.
  void flags_changed() { stale_ = stale_radii_ = true; }

  // At most `steps` FIRE steps, until the largest overlap (over the
  // smaller radius, every process's) is at most `done`. Returns it.
  // Collective.
  double run(int steps, double done);

  // The deepest overlap of owned body k now (over its radius).
  double deepest(int k) const;
  // Over the owned movable bodies at full size: the largest overlap beyond
  // what each pair overlapped at the start (over rmin), and how many of
  // them overlap by more than `above` of the smaller radius. Not collective.
  double worst_at_full_size(double above, std::int64_t &count) const;

  std::int64_t steps() const { return steps_; }

private:
  struct Neighbour {
    int j;
    double allowed;    // what the pair overlapped at the start (two matrix spheres)
  };
  HostHooks &host_;
  Zone &zone_;
  const Domain &domain_;
  double tol_, rmin_, skin_, step_max_;
  double scale_ = 1, pull_ = 0, pad_ = 0;
  bool stale_ = true, stale_radii_ = true;
  std::int64_t steps_ = 0;
  double moved_ = 0;                          // the largest move since the lists (global)
  std::vector<std::vector<Neighbour>> near_;  // per moving body
  std::vector<Vec3> built_, v_, f_;           // per moving body
  std::vector<double> radius_;                // per body: its radius now, 0 when absent
  std::vector<unsigned char> movable_;        // per body
  std::vector<int> rank_;                     // bodies' (id, place) order
  std::vector<int> slot_;                     // a body's index in `moving`, or -1
  std::vector<unsigned char> walled_;         // per moving body: a wall or region within reach

  void update_radii();
  void build_lists();
  double forces();
  void move(double dt);
  double reduce(double worst, double &power, double &vnorm, double &fnorm);
};

}    // namespace reinforce
