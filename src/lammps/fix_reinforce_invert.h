// fix reinforce/invert for LAMMPS: relocates the matrix spheres that overlap
// reinforcement bars (DESIGN.md). This adapter translates LAMMPS's atoms into
// the engine's view and back and owns LAMMPS's communication; the algorithm
// lives in src/core (reinforce::run_invocation).
//
//   fix ID group-ID reinforce/invert N rebar-group-ID keyword value ...
//
// Built against the packaged library and registered at run time by
// lmp_reinforce; the FixStyle block below also lets the two files be dropped
// into a LAMMPS source tree.

#ifdef FIX_CLASS
// clang-format off
FixStyle(reinforce/invert,FixReinforceInvert);
// clang-format on
#else

#ifndef LMP_FIX_REINFORCE_INVERT_H
#define LMP_FIX_REINFORCE_INVERT_H

#include "fix.h"

#include <array>

#include "fix_options.h"
#include "invocation.h"

#include <vector>

namespace LAMMPS_NS {

class FixReinforceInvert : public Fix {
public:
  FixReinforceInvert(class LAMMPS *, int, char **);
  ~FixReinforceInvert() override;
  int setmask() override;
  void init() override;
  void setup_pre_exchange() override;
  void pre_exchange() override;
  double compute_vector(int) override;

  // Per-atom "pending" flag (1 = target waiting for a new place): it must
  // follow atoms that migrate between rounds and reach their ghost copies.
  void grow_arrays(int) override;
  void copy_arrays(int, int, int) override;
  void set_arrays(int) override;
  int pack_exchange(int, double *) override;
  int unpack_exchange(int, double *) override;
  int pack_forward_comm(int, int *, double *, int, int *) override;
  void unpack_forward_comm(int, int, double *) override;
  double memory_usage() override;

private:
  class Host;    // reinforce::HostHooks on LAMMPS's atoms and communication
  friend class Host;

  reinforce::FixOptions options;
  int rebar_group = -1, rebar_bit = 0;
  class Region *region = nullptr;
  std::vector<int> pending;
  bool invoked = false;    // the relocation at the start of the first run is done
  std::array<double, reinforce::kOutputSize> totals = {};

  void check_styles();
  void find_groups_and_region();
  void invoke();
};

}    // namespace LAMMPS_NS

#endif
#endif
