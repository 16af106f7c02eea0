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
#include "invocation.h"

#include <memory>

namespace reinforce {
class MpiExchange;
}

namespace LAMMPS_NS {

class FixReinforceInvert : public Fix, private reinforce::HostHooks {
public:
  FixReinforceInvert(class LAMMPS *, int, char **);
  ~FixReinforceInvert();
  int setmask();
  void init();
  void setup_pre_exchange();
  void pre_exchange();
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
  double user_cutghost_ = -1;                           // >= 0 while the ghost cutoff is raised
  std::unique_ptr<reinforce::MpiExchange> exchange_;    // the rounds' results, per invocation

  void invoke();
  void check_multisphere_bodies();

  // reinforce::HostHooks
  void refresh() override;
  reinforce::AtomArrays atoms() override;
  void set_pending(int local, bool pending) override;
  void forward_pending() override;
  void ensure_ghost_cutoff(double reach) override;
  double ghost_reach(int d);
  bool granular_ghosts();
  void restore_ghost_cutoff() override;
  reinforce::Domain placement_domain() override;
  void move(int local, reinforce::Vec3 x, double r) override;
  void remove(std::vector<int> &locals) override;
  double sum(double v) override;
  double max(double v) override;
  std::vector<double> gather_all(const std::vector<double> &mine) override;
  void post_results(const std::vector<double> &mine, const std::vector<int> &ranks) override;
  std::vector<double> collect_results(const std::vector<int> &ranks) override;
  void finish_results() override;
  double wall_time() override;
  void log(const std::string &line) override;
  void fail(const std::string &message) override;
};

}    // namespace LAMMPS_NS

#endif
#endif
