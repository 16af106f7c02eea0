// The engine's host on a LAMMPS-family fix: reinforce::HostHooks on the
// host's atoms and communication, for one invocation (the MPI hooks are
// reinforce::MpiHooks). run_invocation() calls every collective hook on
// all processes; move() and remove() only on the processes of the current
// round. It is built from a view of what it needs (FixHostView), not from
// the fix. Internal to the shared layer's .cpp files (C++17).
#pragma once

#include "reinforce_mpi_hooks.h"
#include "reinforce_pending_flags.h"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace reinforce {
class Boundaries;
}

namespace LAMMPS_NS {

class Atom;
class Comm;
class Domain;
class Fix;
class Region;

// What the host needs of the fix (ReinforceFixBase::invoke fills it): the
// host's objects, the fix's groups, region and pending flags, and the
// fix's answers that differ by host.
struct FixHostView {
  Atom *atom = nullptr;
  Comm *comm = nullptr;
  Domain *domain = nullptr;
  Fix *fix = nullptr;    // whose per-atom data the forward communication sends: the flags
  MPI_Comm world = MPI_COMM_NULL;
  reinforce::PendingFlags *pending = nullptr;
  Region *region = nullptr;    // the region keyword's, or null
  int group_bit = 0, rebar_bit = 0;
  // The rebar of the host's other reinforce/invert fixes: left alone.
  int frozen_bits = 0;
  std::string frozen_by;

  std::function<double(int d)> ghost_reach;    // beyond the subdomain in dimension d
  std::function<double(double reach)> ghost_cutoff_for;
  std::function<void()> ghost_cutoff_restored;
  std::function<std::shared_ptr<const reinforce::Boundaries>()> walls_in_view;
  std::function<bool(double cutoff)> build_neighbour_lists;
  std::function<void(int local, std::vector<int> &out)> neighbours;
  std::function<void(std::vector<double> &, int, bool)> forward;    // HostHooks::forward
  std::function<void(int local)> moved;    // after an atom got its new place
  std::function<void(const std::string &)> log, warn, fail;
};

class FixHost : public reinforce::MpiHooks {
public:
  explicit FixHost(FixHostView view);
  // A raised ghost cutoff is put back on every way out of the invocation,
  // also when an ERROR unwinds through it (a host built with exceptions, or
  // used as a library): the host's next run must not keep the raised value.
  ~FixHost() override { restore_ghost_cutoff(); }
  FixHost(const FixHost &) = delete;
  FixHost &operator=(const FixHost &) = delete;

  void refresh() override;
  reinforce::AtomArrays atoms() override;
  void set_pending(int local, bool flag) override;
  void forward_pending() override;
  void forward(std::vector<double> &values, int width, bool positions) override
  {
    v.forward(values, width, positions);
  }
  reinforce::GhostCutoff ensure_ghost_cutoff(double reach) override;
  void restore_ghost_cutoff() override;
  reinforce::Domain placement_domain() override;
  void move(int local, reinforce::Vec3 x, double r) override;
  void remove(std::vector<int> &locals) override;
  bool build_neighbour_lists(double cutoff) override { return v.build_neighbour_lists(cutoff); }
  void neighbours(int local, std::vector<int> &out) override { v.neighbours(local, out); }
  void log(const std::string &line) override { v.log(line); }
  void warn(const std::string &message) override { v.warn(message); }
  void fail(const std::string &message) override { v.fail(message); }

private:
  double ghost_reach() const;    // the shortest over the three dimensions
  FixHostView v;
  reinforce::PendingFlags &pending;
  double saved_cutghostuser = 0;
  bool raised = false;
};

}    // namespace LAMMPS_NS
