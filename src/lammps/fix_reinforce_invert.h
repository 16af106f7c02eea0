// fix reinforce/invert for LAMMPS: relocates the matrix spheres that overlap
// reinforcement bars (docs/fix_reinforce_invert.rst). The fix is written
// once for the LAMMPS family (src/host, ReinforceFixBase); this file and its
// .cpp hold only what LAMMPS does its own way.
//
//   fix ID group-ID reinforce/invert N rebar-group-ID keyword value ...
//
// One source for two builds (README, layout table):
//  * packaged: against Debian's LAMMPS 2021 library, registered at run time
//    by lmp_reinforce (REINFORCE_LAMMPS_SOURCE_BUILD=0);
//  * source-built: against a current LAMMPS tree, as reinforceplugin.so
//    (plugin/) or as the in-tree package REINFORCE (package/), with
//    REINFORCE_LAMMPS_SOURCE_BUILD=1: LAMMPS's occasional neighbour list.
// The plugin's CMake sets the macro; elsewhere it is 1 exactly when the
// headers of a source tree are on the include path (neigh_request.h, which
// Debian's liblammps-dev does not ship).

#ifdef FIX_CLASS
// clang-format off
FixStyle(reinforce/invert,FixReinforceInvert);
// clang-format on
#else

#ifndef LMP_FIX_REINFORCE_INVERT_H
#define LMP_FIX_REINFORCE_INVERT_H

#ifndef REINFORCE_LAMMPS_SOURCE_BUILD
#if __has_include("neigh_request.h")
#define REINFORCE_LAMMPS_SOURCE_BUILD 1
#else
#define REINFORCE_LAMMPS_SOURCE_BUILD 0
#endif
#endif

#include "reinforce_fix_base.h"

#include <string>

namespace LAMMPS_NS {

class FixReinforceInvert : public ReinforceFixBase {
public:
  FixReinforceInvert(class LAMMPS *, int, char **);
  int pack_forward_comm(int, int *, double *, int, int *) override;
  void unpack_forward_comm(int, int, double *) override;
#if REINFORCE_LAMMPS_SOURCE_BUILD
  void init() override;
  void init_list(int, class NeighList *) override;
#endif

protected:
  void check_host() override;
  bool in_body(Fix &other, int i) override;
#if REINFORCE_LAMMPS_SOURCE_BUILD
  bool build_neighbour_lists(double cutoff) override;
  void neighbours(int local, std::vector<int> &out) override;
  void ghost_cutoff_restored() override;

private:
  // The host's occasional full list, its cutoff (0: none requested, and
  // why), and which way the latest invocation of this run found the
  // targets (-1: none yet, 0: the engine's grid, 1: the list), so that the
  // log says it once per change.
  class NeighList *list = nullptr;
  double list_cutoff = 0;
  std::string list_why;
  int list_used = -1;
  bool binned = false;        // bins set up for a raised ghost cutoff
  std::vector<int> row;       // the list's row of each owned atom
  double query_cutoff = 0;    // neighbours() gives atoms this close
  void request_neighbour_list();
#endif
};

}    // namespace LAMMPS_NS

#endif
#endif
