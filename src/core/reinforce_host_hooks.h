// What the engine asks of a host (the LAMMPS and LIGGGHTS adapters
// implement it with their own atoms and communication): its atoms, its
// ghosts, its domain, moves and removals, reductions, exchange, log.
#pragma once

#include "reinforce_domain.h"
#include "reinforce_vec3.h"

#include <cstdint>
#include <string>
#include <vector>

namespace reinforce {

// A stage that runs longer than this (seconds) says on the log how far it
// got, at most this often.
constexpr double kProgressEvery = 5;

// The most values per atom HostHooks::forward sends.
constexpr int kForwardWidth = 4;

// A host's per-atom arrays, owned atoms first then ghosts.
struct AtomArrays {
  int nlocal = 0, nall = 0;
  double **x = nullptr;
  const double *radius = nullptr;
  // Atom IDs, the host's own array (hosts have 32- or 64-bit IDs): exactly
  // one of the two is set.
  const int *tag32 = nullptr;
  const std::int64_t *tag64 = nullptr;
  const int *mask = nullptr;
  const int *pending = nullptr;    // the fix's per-atom flag: 1 = target waiting for a place
  int group_bit = 0, rebar_bit = 0;
  // Atoms this fix never moves, deletes or takes as targets, whatever its
  // group: the rebar of the host's other reinforce/invert fixes (their
  // group bits, ORed), named in `frozen_by` for the log ("fix ID", ...).
  int frozen_bits = 0;
  std::string frozen_by;

  std::int64_t id(int i) const { return tag64 ? tag64[i] : tag32[i]; }
};

// The ghost cutoff before and after ensure_ghost_cutoff (raised: it had to
// grow), for the core's log line.
struct GhostCutoff {
  double before = 0, after = 0;
  bool raised = false;
};

class HostHooks {
public:
  virtual ~HostHooks() = default;

  // Wraps periodic coordinates, migrates atoms to their owners, rebuilds the
  // ghosts and forwards the pending flags to them.
  virtual void refresh() = 0;
  virtual AtomArrays atoms() = 0;
  virtual void set_pending(int local, bool pending) = 0;
  // Sends the pending flags of owned atoms to their ghost copies.
  virtual void forward_pending() = 0;

  // Makes the ghost cutoff at least `reach` (or stops with an error that
  // names the value needed), without logging; restore_ghost_cutoff undoes
  // a raise.
  virtual GhostCutoff ensure_ghost_cutoff(double reach) = 0;
  virtual void restore_ghost_cutoff() = 0;
  // The box, its periodicity, this process's subdomain and view, the region.
  virtual Domain placement_domain() = 0;

  // New centre and radius for an owned atom (the host keeps the density and
  // clears the pending flag), and removal of owned atoms.
  virtual void move(int local, Vec3 x, double r) = 0;
  virtual void remove(std::vector<int> &locals) = 0;

  // Global reductions over all processes: of one value; and in one
  // collective, of each element of two vectors (each the same length on
  // every process), summed and taken the largest.
  virtual double sum(double v) = 0;
  virtual double max(double v) = 0;
  virtual void sum_and_max(std::vector<double> &sums, std::vector<double> &maxima) = 0;

  // Forward communication of per-atom values, as the host sends its atoms'
  // coordinates to their ghost copies: `values` holds `width` (at most
  // kForwardWidth) values per atom, owned atoms then ghosts (AtomArrays'
  // nall rows); each ghost's row is overwritten by its owner's. With
  // `positions`, the first three values of a row are a position, shifted
  // by the box length where the ghost is a periodic image, as the host
  // shifts its ghosts' coordinates. Collective; the atoms and ghosts stay.
  virtual void forward(std::vector<double> &values, int width, bool positions) = 0;
  // Every process's values, concatenated in rank order (collective).
  virtual std::vector<double> gather_all(const std::vector<double> &mine) = 0;
  // A round's results, exchanged without a barrier between partners
  // (`ranks`: ascending, the same set every round, symmetric between
  // processes; this process's own rank in it is skipped): post_results
  // sends this process's values to each partner and returns at once;
  // collect_results returns the partners' values of the oldest round posted
  // and not yet collected, concatenated in rank order, waiting only for
  // those not yet there; finish_results, after the last collect, waits
  // until every posted value has been sent. Every process posts and
  // collects the same rounds in the same order.
  virtual void post_results(const std::vector<double> &mine, const std::vector<int> &ranks) = 0;
  virtual std::vector<double> collect_results(const std::vector<int> &ranks) = 0;
  virtual void finish_results() = 0;

  // Optional: the host's own neighbour list, for the overlap check that
  // finds the targets (the only query the engine sends to it; the candidate
  // search stays on the engine's grid: docs/design.md, "Targets").
  // build_neighbour_lists is called once per invocation, at the same point
  // on every process (it may be collective), after the ghosts are final;
  // it returns false when the host has no list that reaches `cutoff` (the
  // engine then uses its own grid, with the same result), true when it
  // built a full list over the current atoms with a row for each owned
  // atom; then neighbours(local), for an owned atom, gives the local
  // indices (owned or ghost) of every atom within `cutoff` of it, in any
  // order (rows for ghosts are not needed).
  virtual bool build_neighbour_lists(double cutoff)
  {
    (void)cutoff;
    return false;
  }
  virtual void neighbours(int local, std::vector<int> &out)
  {
    (void)local;
    out.clear();
  }
  virtual double wall_time() = 0;
  virtual void log(const std::string &line) = 0;
  // One WARNING line (the host's own, printed once): the message without
  // the "WARNING: " the host puts before it, without a newline.
  virtual void warn(const std::string &message) = 0;
  virtual void fail(const std::string &message) = 0;    // does not return
};

}    // namespace reinforce
