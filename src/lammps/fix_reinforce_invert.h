// fix reinforce/invert for LAMMPS: relocates the matrix spheres that overlap
// reinforcement bars (docs/design.md). This adapter translates LAMMPS's atoms into
// the engine's view and back and owns LAMMPS's communication; the algorithm
// lives in src/core (reinforce::run_invocation).
//
//   fix ID group-ID reinforce/invert N rebar-group-ID keyword value ...
//
// One source for two builds (README, layout table):
//  * packaged: against Debian's LAMMPS 2021 library, registered at run time
//    by lmp_reinforce (REINFORCE_LAMMPS_SOURCE_BUILD=0);
//  * source-built: against a current LAMMPS tree, as reinforceplugin.so
//    (plugin/) or as the in-tree package REINFORCE (package/), with
//    REINFORCE_LAMMPS_SOURCE_BUILD=1; the FixStyle block below registers it
//    there. Only fix_reinforce_invert.cpp differs, in a few #if blocks.
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

#include "fix.h"

#include <memory>
#include <vector>

// No engine header here: LAMMPS's own files include this one (style_fix.h)
// with LAMMPS's C++ standard, while the engine needs C++17.
namespace reinforce {
struct FixOptions;
}

namespace LAMMPS_NS {

class FixReinforceInvert : public Fix {
public:
  FixReinforceInvert(class LAMMPS *, int, char **);
  ~FixReinforceInvert() override;
  int setmask() override;
  void init() override;
  void setup_pre_exchange() override;
  void post_run() override;
#if REINFORCE_LAMMPS_SOURCE_BUILD
  void init_list(int, class NeighList *) override;
#endif
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

  std::unique_ptr<reinforce::FixOptions> parsed;    // the fix's arguments
  reinforce::FixOptions &options;
  int rebar_group = -1, rebar_bit = 0;
  class Region *region = nullptr;
  std::vector<int> pending;
  bool invoked = false;       // the relocation at the start of the first run is done
  bool setup_seen = false;    // setup_pre_exchange ran in this run's setup
  // Atoms moved by the latest invocation in the group of each fix that
  // anchors per-atom positions (spring/self), by fix index.
  std::vector<std::pair<int, double>> anchored;
  class NeighList *list = nullptr;    // source-built: the host's occasional full list
  std::vector<double> totals;         // f_ID[1..], the latest invocation
#if REINFORCE_LAMMPS_SOURCE_BUILD
  // The list's cutoff (0: none requested, and why), and which way the
  // latest invocation of this run found the targets (-1: none yet, 0: the
  // engine's grid, 1: the list), so that the log says it once per change.
  double list_cutoff = 0;
  std::string list_why;    // <string>: exported by LAMMPS's pointers.h
  int list_used = -1;
  void request_neighbour_list();
#endif

  // error->all, with rank 0's screen and log flushed before its exception
  // leaves (a source-built LAMMPS throws there; see the .cpp).
  void stop(const char *file, int line, const std::string &message);
  bool done() const;    // N = 0, relocated once
  void check_styles();
  void find_groups_and_region();
  void check_rigid_bodies();
  void check_walls();
  bool shares_matrix_atoms(const class Fix *other);
  void find_other_rebar(int &bits, std::string &names);
  void invoke();
};

}    // namespace LAMMPS_NS

#endif
#endif
