// LIGGGHTS adapter of fix reinforce/invert: translates the host's atoms and
// communication into reinforce::HostHooks; the algorithm is in src/core.
// The same two files serve both builds: liggghts_reinforce (packaged
// LIGGGHTS, style registered by register_style.cpp) and a LIGGGHTS source
// tree (dropin/install.sh), where LIGGGHTS's style generator reads the
// FixStyle block below.
#ifdef FIX_CLASS
// clang-format off
FixStyle(reinforce/invert,FixReinforceInvert)
// clang-format on
#else

#ifndef REINFORCE_LIGGGHTS_FIX_REINFORCE_INVERT_H
#define REINFORCE_LIGGGHTS_FIX_REINFORCE_INVERT_H

#include "fix.h"
#include "reinforce_invocation.h"

#include <cstdint>
#include <memory>
#include <string>
#include <unordered_set>
#include <vector>

namespace LAMMPS_NS {

class PrimitiveWall;
// A primitive wall's type (PRIMITIVE_WALL_DEFINITIONS::WallType) and its
// parameters, which LIGGGHTS keeps private (reinforce_primitive_wall_access.cpp).
int primitive_wall_shape(const PrimitiveWall &wall, std::vector<double> &param);

class FixReinforceInvert : public Fix {
public:
  FixReinforceInvert(class LAMMPS *, int, char **);
  ~FixReinforceInvert();
  int setmask();
  void init();
  void setup_pre_exchange();
  void pre_exchange();
  void post_run();
  double compute_vector(int);

  void grow_arrays(int);
  void copy_arrays(int, int, int);
  int pack_exchange(int, double *);
  int unpack_exchange(int, double *);
  int pack_comm(int, int *, double *, int, int *);
  void unpack_comm(int, int, double *);

private:
  reinforce::FixOptions options_;
  int rebar_bit_ = 0;
  class Region *region_ = nullptr;
  int *pending_ = nullptr;    // per atom: 1 = target waiting for a place
  int nmax_ = 0;              // length of pending_
  std::array<double, reinforce::kOutputSize> output_ = {};
  bool invoked_ = false;
  // The walls of the wall fixes, read at each invocation (read_walls), and
  // the engine's copy of them (with periodic images of the triangles).
  std::vector<reinforce::Plane> wall_planes_;
  std::vector<reinforce::Cylinder> wall_cylinders_;
  std::vector<reinforce::Triangle> wall_triangles_;
  std::shared_ptr<const reinforce::Boundaries> walls_;
  double walls_margin_ = -1;    // how far beyond the box walls_ holds triangle images
  // fix spring/self: the atoms of its group this invocation moved (by ID).
  struct Anchors {
    std::string id;
    int bit;
    std::unordered_set<std::int64_t> moved;
  };
  std::vector<Anchors> anchors_;

  void invoke();
  void check_multisphere_bodies();
  void read_walls();
  bool shares_atoms(int bit);
  void cannot_see_walls(const Fix &wall, std::string &skipped);
  std::string add_primitive_wall(const PrimitiveWall &wall);
  int add_mesh(class FixMeshSurface &mesh);
  std::shared_ptr<const reinforce::Boundaries> walls_in_view();
  void find_anchors();
  void warn_anchors();

  double ghost_reach(int d);
  bool granular_ghosts();
  void log(const std::string &line);
  void warn(const std::string &message);
  void fail(const std::string &message);    // does not return

  class Host;    // reinforce::HostHooks on LIGGGHTS's atoms and communication
  friend class Host;
};

}    // namespace LAMMPS_NS

#endif
#endif
