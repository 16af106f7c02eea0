// fix reinforce/invert for LIGGGHTS: relocates the matrix spheres that
// overlap reinforcement bars (docs/fix_reinforce_invert.rst). The fix is
// written once for the LAMMPS family (src/host, ReinforceFixBase); this
// file and its .cpp hold only what LIGGGHTS does its own way, and
// reinforce_liggghts_walls.* read its walls and meshes.
// The same files serve both builds: liggghts_reinforce (packaged LIGGGHTS,
// style registered by register_style.cpp) and a LIGGGHTS source tree
// (dropin/install.sh), where LIGGGHTS's style generator reads the FixStyle
// block below.
#ifdef FIX_CLASS
// clang-format off
FixStyle(reinforce/invert,FixReinforceInvert)
// clang-format on
#else

#ifndef REINFORCE_LIGGGHTS_FIX_REINFORCE_INVERT_H
#define REINFORCE_LIGGGHTS_FIX_REINFORCE_INVERT_H

#include "reinforce_fix_base.h"

#include <memory>
#include <string>

namespace LAMMPS_NS {

class LiggghtsWalls;

class FixReinforceInvert : public ReinforceFixBase {
public:
  FixReinforceInvert(class LAMMPS *, int, char **);
  ~FixReinforceInvert() override;
  int setmask() override;
  int pack_comm(int, int *, double *, int, int *) override;
  void unpack_comm(int, int, double *) override;

protected:
  void check_host() override;
  void check_region(Region &region) override;
  bool in_body(Fix &other, int i) override;
  std::string read_walls(Fix &wall) override;
  void forget_walls() override;
  std::shared_ptr<const reinforce::Boundaries> walls_in_view() override;
  double ghost_reach(int d) override;
  double ghost_cutoff_for(double reach) override;

private:
  std::unique_ptr<LiggghtsWalls> walls;
  bool granular_ghosts() const;
};

}    // namespace LAMMPS_NS

#endif
#endif
