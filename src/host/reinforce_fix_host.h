// The engine's host on a LAMMPS-family fix: reinforce::HostHooks on the
// host's atoms and communication, for one invocation (the MPI hooks are
// reinforce::MpiHooks). run_invocation() calls every collective hook on
// all processes; move() and remove() only on the processes of the current
// round. Internal to the shared layer's .cpp files (C++17).
#pragma once

#include "reinforce_fix_base.h"

#include "reinforce_mpi_hooks.h"

#include <string>
#include <vector>

namespace reinforce {
namespace host_flags {
// Marks of the per-atom pending flag.
constexpr int kPresent = 0;    // not waiting (rebar, matrix, relocated, kept)
constexpr int kPending = 1;    // a target waiting for its new place
constexpr int kDoomed = 2;     // removed: leaves at the next refresh (hosts without AtomVec::copy)
}    // namespace host_flags
}    // namespace reinforce

namespace LAMMPS_NS {

class ReinforceFixBase::Host : public reinforce::MpiHooks {
public:
  explicit Host(ReinforceFixBase &fix);
  // A raised ghost cutoff is put back on every way out of the invocation,
  // also when an ERROR unwinds through it (a host built with exceptions, or
  // used as a library): the host's next run must not keep the raised value.
  ~Host() override { restore_ghost_cutoff(); }
  Host(const Host &) = delete;
  Host &operator=(const Host &) = delete;

  void refresh() override;
  reinforce::AtomArrays atoms() override;
  void set_pending(int local, bool flag) override;
  void forward_pending() override;
  reinforce::GhostCutoff ensure_ghost_cutoff(double reach) override;
  void restore_ghost_cutoff() override;
  reinforce::Domain placement_domain() override;
  void move(int local, reinforce::Vec3 x, double r) override;
  void remove(std::vector<int> &locals) override;
  bool build_neighbour_lists(double cutoff) override { return f.build_neighbour_lists(cutoff); }
  void neighbours(int local, std::vector<int> &out) override { f.neighbours(local, out); }
  void log(const std::string &line) override { f.log(line); }
  void warn(const std::string &message) override { f.warn(message); }
  void fail(const std::string &message) override;

  // The rebar of the host's other reinforce/invert fixes (ReinforceFixBase::
  // find_other_rebar): left alone.
  int frozen_bits = 0;
  std::string frozen_by;

private:
  double ghost_reach() const;    // the shortest over the three dimensions
  ReinforceFixBase &f;
  double saved_cutghostuser = 0;
  bool raised = false;
};

}    // namespace LAMMPS_NS
