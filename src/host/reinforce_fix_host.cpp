// The engine's host on a LAMMPS-family fix (reinforce_fix_host.h).

#include "reinforce_fix_host.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "region.h"

#include "reinforce_host_api.h"

// Deleting atoms the host's own way needs AtomVec::copy, which Debian's
// LAMMPS 2021 package does not declare (it ships no atom_vec.h).
#if __has_include("atom_vec.h")
#include "atom_vec.h"
#define REINFORCE_HOST_COPIES_ATOMS 1
#else
#define REINFORCE_HOST_COPIES_ATOMS 0
#endif

#include <algorithm>
#include <cstdint>
#include <limits>
#include <utility>

using namespace LAMMPS_NS;
using Mark = reinforce::PendingFlags;

namespace {

// Atom IDs as the host stores them: 32-bit, or 64-bit (LAMMPS bigbig).
[[maybe_unused]] void view_tags(reinforce::AtomArrays &a, const int *tag)
{
  a.tag32 = tag;
}
[[maybe_unused]] void view_tags(reinforce::AtomArrays &a, const std::int64_t *tag)
{
  a.tag64 = tag;
}

}    // namespace

FixHost::FixHost(FixHostView view) : MpiHooks(view.world), v(std::move(view)), pending(*v.pending)
{
}

// The refresh the hosts' Monte Carlo fixes do inside pre_exchange, plus
// comm->setup(): at setup_pre_exchange of the first run it has not been
// called yet, and it also applies a changed ghost cutoff.
void FixHost::refresh()
{
  v.domain->pbc();
  v.domain->reset_box();
  v.comm->setup();
#if !REINFORCE_HOST_COPIES_ATOMS
  // comm->exchange() runs AtomVec::copy for every atom that leaves the
  // subdomain, and with one process in a dimension drops it; with more,
  // the neighbours take it only if its coordinate lies in their subdomain.
  // So an atom whose x is the largest double just before an exchange is
  // deleted as delete_atoms does it, on every process grid (domain->pbc()
  // must not run in between: it would try to wrap it). Copying the rows of
  // atom->peratom instead is not safe there: some registered pointers are
  // never initialised (atom->vest_temp).
  for (int i = 0; i < v.atom->nlocal; ++i)
    if (pending[i] == Mark::kDoomed) v.atom->x[i][0] = std::numeric_limits<double>::max();
#endif
  v.comm->exchange();
  v.atom->nghost = 0;
  v.comm->borders();
  forward_pending();
}

reinforce::AtomArrays FixHost::atoms()
{
  Atom *atom = v.atom;
  pending.grow(atom->nmax);
  reinforce::AtomArrays a;
  a.nlocal = atom->nlocal;
  a.nall = atom->nlocal + atom->nghost;
  a.x = atom->x;
  a.radius = atom->radius;
  view_tags(a, atom->tag);
  a.mask = atom->mask;
  a.pending = pending.data();
  a.group_bit = v.group_bit;
  a.rebar_bit = v.rebar_bit;
  a.frozen_bits = v.frozen_bits;
  a.frozen_by = v.frozen_by;
  return a;
}

void FixHost::set_pending(int local, bool flag)
{
  pending[local] = flag ? Mark::kPending : Mark::kPresent;
}

// Also with one process: periodic images are ghosts too.
void FixHost::forward_pending()
{
  reinforce::host_api::forward_comm(v.comm, v.fix, 0);
}

double FixHost::ghost_reach() const
{
  return std::min({v.ghost_reach(0), v.ghost_reach(1), v.ghost_reach(2)});
}

reinforce::GhostCutoff FixHost::ensure_ghost_cutoff(double reach)
{
  reinforce::GhostCutoff g;
  g.before = g.after = ghost_reach();
  if (g.before >= reach) return g;
  // A second raise (the regrowth) restores the user's value too.
  if (!raised) saved_cutghostuser = v.comm->cutghostuser;
  v.comm->cutghostuser = v.ghost_cutoff_for(reach);
  raised = true;
  refresh();    // comm->setup() with the new cutoff, then the ghosts again
  g.after = ghost_reach();
  g.raised = true;
  return g;
}

void FixHost::restore_ghost_cutoff()
{
  if (!raised) return;
  raised = false;
  v.comm->cutghostuser = saved_cutghostuser;
  v.comm->setup();
  v.ghost_cutoff_restored();
}

reinforce::Domain FixHost::placement_domain()
{
  Domain *domain = v.domain;
  reinforce::Domain d;
  for (int k = 0; k < 3; ++k) {
    d.lo[k] = domain->boxlo[k];
    d.hi[k] = domain->boxhi[k];
    d.periodic[k] = domain->periodicity[k] != 0;
    d.view_lo[k] = domain->sublo[k] - v.ghost_reach(k);
    d.view_hi[k] = domain->subhi[k] + v.ghost_reach(k);
    d.sub_lo[k] = domain->sublo[k];
    d.sub_hi[k] = domain->subhi[k];
  }
  // The whole sphere inside: its centre matches and no surface of the
  // region lies within r of it (Region::surface, as fix wall/region finds
  // its contacts; for side out it measures to the excluded body). A moving
  // region was set for this step by prematch() in invoke().
  if (Region *region = v.region)
    d.region = [region](const reinforce::Vec3 &x, double r) {
      return region->match(x.x, x.y, x.z) != 0 && region->surface(x.x, x.y, x.z, r) == 0;
    };
  d.walls = v.walls_in_view();
  return d;
}

void FixHost::move(int i, reinforce::Vec3 x, double r)
{
  Atom *atom = v.atom;
  const double scale = r / atom->radius[i];
  for (int k = 0; k < 3; ++k) {
    atom->x[i][k] = x[k];
    atom->v[i][k] = 0.0;
    if (atom->omega_flag) atom->omega[i][k] = 0.0;
  }
  atom->radius[i] = r;
  atom->rmass[i] *= scale * scale * scale;    // the material density is kept
  pending[i] = Mark::kPresent;
  v.moved(i);
}

#if REINFORCE_HOST_COPIES_ATOMS
// As delete_atoms and fix evaporate do: the last owned atom moves into each
// hole (AtomVec::copy also carries every fix's per-atom data), highest
// index first, so a moved atom is never one still to be removed. Ghosts
// are stale until the refresh that follows every round (collective), and
// nothing looks at them before it.
void FixHost::remove(std::vector<int> &locals)
{
  std::sort(locals.rbegin(), locals.rend());
  for (int i : locals) {
    v.atom->avec->copy(v.atom->nlocal - 1, i, 1);
    v.atom->nlocal--;
  }
}
#else
// Only the processes of one round call this, so the atoms are only marked
// here; the next refresh (collective) deletes them. Until then nothing
// looks at them, and afterwards they are gone from every view.
void FixHost::remove(std::vector<int> &locals)
{
  for (int i : locals) pending[i] = Mark::kDoomed;
}
#endif
