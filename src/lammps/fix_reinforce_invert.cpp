// fix reinforce/invert: the LAMMPS adapter (see fix_reinforce_invert.h).
//
// Note on messages: only the std::string overloads of error->all() and
// utils::logmesg() may be called (see fmt_compat/fmt/format.h), so every
// message is built here as a std::string.
//
// REINFORCE_LAMMPS_SOURCE_BUILD (fix_reinforce_invert.h) selects what the
// host offers; each #if below says why the two builds differ there:
//  1. atom deletion: AtomVec::copy (source-built) or an exchange that drops
//     atoms moved out of the box (packaged: no atom_vec.h);
//  2. the host's occasional neighbour list (source-built: neigh_request.h);
//  3. renamed API: Comm::forward_comm(Fix *) and Domain::get_region_by_id
//     (current LAMMPS) against forward_comm_fix and find_region (2021);
//     NeighRequest::set_cutoff_fixed (since August 2026) against set_cutoff.

#if __cplusplus < 201703L
#error "fix reinforce/invert needs C++17: -D CMAKE_CXX_STANDARD=17 (LAMMPS before 22Jul2025)"
#endif

#include "fix_reinforce_invert.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "group.h"
#include "modify.h"
#include "region.h"
#include "update.h"
#if REINFORCE_LAMMPS_SOURCE_BUILD
#include "atom_vec.h"
#include "force.h"
#include "neigh_list.h"
#include "neigh_request.h"
#include "neighbor.h"
#include "pair.h"
#endif

#include "reinforce_fix_options.h"
#include "reinforce_invocation.h"
#include "reinforce_mpi_hooks.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <string>
#include <type_traits>

using namespace LAMMPS_NS;
using namespace FixConst;

namespace {

// The host's atom IDs as the engine reads them, in place (tagint is int or
// int64_t, by the host's build).
template <class Tag> void set_ids(reinforce::AtomArrays &a, const Tag *tag)
{
  constexpr bool narrow = std::is_same<Tag, int>::value;
  static_assert(narrow || std::is_same<Tag, std::int64_t>::value, "tagint: int or int64_t");
  a.tag32 = narrow ? reinterpret_cast<const int *>(tag) : nullptr;
  a.tag64 = narrow ? nullptr : reinterpret_cast<const std::int64_t *>(tag);
}

// Marks of the per-atom pending flag.
constexpr int kPresent = 0;    // not waiting (rebar, matrix, relocated, kept)
constexpr int kPending = 1;    // a target waiting for its new place
constexpr int kDoomed = 2;     // no place found: to be deleted at the next refresh

#if !REINFORCE_LAMMPS_SOURCE_BUILD
// ---------------------------------------------------------------------------
// [1, packaged] Deletion of atoms, with LAMMPS's own code path for it.
//
// delete_atoms removes an atom by AtomVec::copy() of the last owned atom into
// its slot, which also calls copy_arrays() of every fix holding per-atom data.
// liblammps-dev does not ship atom_vec.h, so AtomVec::copy cannot be called
// from here, and copying the rows registered in atom->peratom generically is
// not safe: in this LAMMPS some registered pointers are never initialised
// (atom->vest_temp), so "skip the null ones" reads garbage.
//
// comm->exchange() runs exactly that AtomVec::copy for every atom that leaves
// the subdomain, and with one process in a dimension drops it; with more, the
// neighbours accept it only if its coordinate lies in their subdomain. So an
// atom whose x coordinate is set to the largest double just before an
// exchange is deleted the way delete_atoms does it, on every process grid.
// (domain->pbc() must not run in between: it would try to wrap it.)
// ---------------------------------------------------------------------------
void mark_doomed_atoms_for_exchange(Atom *atom, const std::vector<int> &pending)
{
  for (int i = 0; i < atom->nlocal; ++i)
    if (pending[i] == kDoomed) atom->x[i][0] = std::numeric_limits<double>::max();
}
#endif

// Comm keeps bordergroup protected. A class derived from it may name the
// member through a pointer to member; no object of this class is made.
struct CommAccess : Comm {
  static int border_group_of(const Comm *c) { return c->*(&CommAccess::bordergroup); }
};

std::string format_count(double v)
{
  char text[32];
  std::snprintf(text, sizeof text, "%.0f", v);
  return text;
}

[[maybe_unused]] std::string format_length(double v)
{
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", v);
  return text;
}

#if REINFORCE_LAMMPS_SOURCE_BUILD
// [3] One cutoff for every type pair: NeighRequest::set_cutoff_fixed since
// LAMMPS's August 2026 feature release, set_cutoff before it. The overload
// taking int is chosen where the newer name exists.
template <class Request>
auto set_fixed_cutoff(Request *request, double cutoff, int)
    -> decltype(request->set_cutoff_fixed(cutoff), void())
{
  request->set_cutoff_fixed(cutoff);
}
template <class Request> void set_fixed_cutoff(Request *request, double cutoff, long)
{
  request->set_cutoff(cutoff);
}
#endif

Region *find_region(Domain *domain, const std::string &name)
{
#if REINFORCE_LAMMPS_SOURCE_BUILD    // [3] current API
  return domain->get_region_by_id(name);
#else
  const int iregion = domain->find_region(name);
  return iregion < 0 ? nullptr : domain->regions[iregion];
#endif
}

}    // namespace

// ---------------------------------------------------------------------------
// The engine's host: LAMMPS's atoms and communication behind
// reinforce::HostHooks (the MPI hooks are reinforce::MpiHooks, shared with
// the LIGGGHTS adapter). run_invocation() calls every collective hook on all
// processes; move() and remove() only on the processes of the current round.
// ---------------------------------------------------------------------------

class FixReinforceInvert::Host : public reinforce::MpiHooks {
public:
  explicit Host(FixReinforceInvert &fix) : MpiHooks(fix.world), f(fix) {}
  // A raised ghost cutoff is put back on every way out of the invocation,
  // also when an ERROR unwinds through it (LAMMPS built with exceptions, or
  // used as a library): the host's next run must not keep the raised value.
  ~Host() override { restore_ghost_cutoff(); }
  Host(const Host &) = delete;
  Host &operator=(const Host &) = delete;

  // The refresh LAMMPS's Monte Carlo fixes do inside pre_exchange, plus
  // comm->setup(): at setup_pre_exchange of the first run it has not been
  // called yet, and it also applies a changed ghost cutoff. The exchange
  // also deletes the atoms remove() marked.
  void refresh() override
  {
    f.domain->pbc();
    f.domain->reset_box();
    f.comm->setup();
#if !REINFORCE_LAMMPS_SOURCE_BUILD    // [1] remove() only marked them
    mark_doomed_atoms_for_exchange(f.atom, f.pending);
#endif
    f.comm->exchange();
    f.atom->nghost = 0;
    f.comm->borders();
    forward_pending();
  }

  reinforce::AtomArrays atoms() override
  {
    Atom *atom = f.atom;
    if (static_cast<int>(f.pending.size()) < atom->nmax) f.grow_arrays(atom->nmax);
    reinforce::AtomArrays a;
    a.nlocal = atom->nlocal;
    a.nall = atom->nlocal + atom->nghost;
    a.x = atom->x;
    a.radius = atom->radius;
    set_ids(a, atom->tag);
    a.mask = atom->mask;
    a.pending = f.pending.data();
    a.group_bit = f.groupbit;
    a.rebar_bit = f.rebar_bit;
    a.frozen_bits = frozen_bits;
    a.frozen_by = frozen_by;
    return a;
  }

  void set_pending(int local, bool flag) override
  {
    f.pending[local] = flag ? kPending : kPresent;
  }

  void forward_pending() override
  {
    // Also with one process: periodic images are ghosts too.
#if REINFORCE_LAMMPS_SOURCE_BUILD    // [3] current API
    f.comm->forward_comm(&f);
#else
    f.comm->forward_comm_fix(&f);
#endif
  }

  reinforce::GhostCutoff ensure_ghost_cutoff(double reach) override
  {
    const double before = std::min({f.comm->cutghost[0], f.comm->cutghost[1], f.comm->cutghost[2]});
    if (before >= reach) return {before, before, false};
    // A second raise (the regrowth) restores the user's value too.
    if (!raised) saved_cutghostuser = f.comm->cutghostuser;
    f.comm->cutghostuser = reach;
    raised = true;
    refresh();    // comm->setup() with the new cutoff, then the ghosts again
    const double after = std::min({f.comm->cutghost[0], f.comm->cutghost[1], f.comm->cutghost[2]});
    return {before, after, true};
  }

  void restore_ghost_cutoff() override
  {
    if (!raised) return;
    raised = false;
    f.comm->cutghostuser = saved_cutghostuser;
    f.comm->setup();
#if REINFORCE_LAMMPS_SOURCE_BUILD
    if (binned) f.neighbor->setup_bins();    // back to the run's ghost extent
#endif
    binned = false;
  }

#if REINFORCE_LAMMPS_SOURCE_BUILD
  // [2] The host's occasional full list (FixReinforceInvert::
  // request_neighbour_list), for the overlap check that finds the targets.
  // Rows for owned atoms only (LAMMPS refuses an occasional binned list with
  // ghost info), their neighbours owned or ghost: what neighbours()
  // promises, and all that check needs. Its cutoff was fixed at init(): a
  // larger request (radii grew since), exclusions, or no list at all are
  // answered "no list", and the engine uses its own grid (same targets).
  //
  // Built as delete_atoms builds its list after a fresh exchange: bins for
  // the current ghost extent (raised or not), neighbor->build(), then
  // build_one(). build() is needed: refresh() moved atoms after LAMMPS last
  // binned them, and only build() bins them again (build_one() does not);
  // and build_one() skips a list built since the last build(), and every
  // list before the first build() of all (at the first run's setup: both
  // step stamps are -1; tests/source_hosts, *_host_list_*, fail without
  // it). The perpetual lists build() makes too are made again by LAMMPS
  // right after pre_exchange, as after fix gcmc and fix atom/swap, which
  // also call neighbor->build() there.
  bool build_neighbour_lists(double cutoff) override
  {
    Neighbor *neighbor = f.neighbor;
    const double ghost = std::min({f.comm->cutghost[0], f.comm->cutghost[1], f.comm->cutghost[2]});
    std::string why;
    if (!f.list)
      why = f.list_why.empty() ? "LAMMPS gave the fix no list" : f.list_why;
    else if (neighbor->exclude || neighbor->includegroup)
      why = "neigh_modify exclude or include is set (the list would leave pairs out)";
    else if (!(cutoff <= f.list_cutoff))
      why = "the matrix-rebar contact " + format_length(cutoff) + " exceeds the list's cutoff " +
            format_length(f.list_cutoff) + " (radii grew since the run began)";
    else if (!(f.list_cutoff <= ghost))
      why = "the ghost cutoff " + format_length(ghost) + " is shorter than the list's cutoff";
    const int used = why.empty() ? 1 : 0;
    if (used != f.list_used)
      log(used ? "fix reinforce/invert: targets found with LAMMPS's occasional full neighbor "
                 "list (cutoff " +
                     format_length(f.list_cutoff) + ")\n"
               : "fix reinforce/invert: targets found with the engine's grid: " + why + "\n");
    f.list_used = used;
    if (!used) return false;

    neighbor->setup_bins();    // bins for the current ghost extent
    binned = true;
    neighbor->build(1);
    neighbor->build_one(f.list);
    row.assign(f.atom->nlocal, -1);
    for (int ii = 0; ii < f.list->inum; ++ii)
      if (f.list->ilist[ii] < f.atom->nlocal) row[f.list->ilist[ii]] = ii;
    query_cutoff = cutoff;
    return true;
  }

  void neighbours(int local, std::vector<int> &out) override
  {
    out.clear();
    if (local < 0 || local >= static_cast<int>(row.size()) || row[local] < 0) return;
    const int i = f.list->ilist[row[local]];
    const int *jlist = f.list->firstneigh[i];
    const double *xi = f.atom->x[i];
    for (int k = 0; k < f.list->numneigh[i]; ++k) {
      const int j = jlist[k] & NEIGHMASK;
      const double dx = xi[0] - f.atom->x[j][0], dy = xi[1] - f.atom->x[j][1],
                   dz = xi[2] - f.atom->x[j][2];
      if (dx * dx + dy * dy + dz * dz <= query_cutoff * query_cutoff) out.push_back(j);
    }
  }
#endif

  reinforce::Domain placement_domain() override
  {
    reinforce::Domain d;
    for (int k = 0; k < 3; ++k) {
      d.lo[k] = f.domain->boxlo[k];
      d.hi[k] = f.domain->boxhi[k];
      d.periodic[k] = f.domain->periodicity[k] != 0;
      d.view_lo[k] = f.domain->sublo[k] - f.comm->cutghost[k];
      d.view_hi[k] = f.domain->subhi[k] + f.comm->cutghost[k];
      d.sub_lo[k] = f.domain->sublo[k];
      d.sub_hi[k] = f.domain->subhi[k];
    }
    // The whole sphere inside: its centre matches and no surface of the
    // region lies within r of it (Region::surface, as fix wall/region
    // finds its contacts; for side out it measures to the excluded body).
    if (Region *region = f.region)
      d.region = [region](const reinforce::Vec3 &x, double r) {
        return region->match(x.x, x.y, x.z) != 0 && region->surface(x.x, x.y, x.z, r) == 0;
      };
    return d;
  }

  void move(int i, reinforce::Vec3 x, double r) override
  {
    Atom *atom = f.atom;
    const double scale = r / atom->radius[i];
    for (int k = 0; k < 3; ++k) {
      atom->x[i][k] = x[k];
      atom->v[i][k] = 0.0;
      if (atom->omega_flag) atom->omega[i][k] = 0.0;
    }
    atom->radius[i] = r;
    atom->rmass[i] *= scale * scale * scale;    // the material density is kept
    f.pending[i] = kPresent;
    for (auto &[ifix, count] : f.anchored)
      if (atom->mask[i] & f.modify->fix[ifix]->groupbit) count += 1;
  }

#if REINFORCE_LAMMPS_SOURCE_BUILD
  // [1] As delete_atoms and fix evaporate do: the last owned atom moves into
  // each hole (AtomVec::copy also carries every fix's per-atom data), highest
  // index first, so a moved atom is never one still to be removed. Ghosts
  // are stale until the refresh that follows every round (collective), and
  // nothing looks at them before it.
  void remove(std::vector<int> &locals) override
  {
    std::sort(locals.rbegin(), locals.rend());
    for (int i : locals) {
      f.atom->avec->copy(f.atom->nlocal - 1, i, 1);
      f.atom->nlocal--;
    }
  }
#else
  // [1] Only the processes of one round call this, so the atoms are only
  // marked here; the next refresh (collective) deletes them. Until then
  // nothing looks at them, and afterwards they are gone from every view.
  void remove(std::vector<int> &locals) override
  {
    for (int i : locals) f.pending[i] = kDoomed;
  }
#endif

  void log(const std::string &line) override
  {
    if (f.comm->me == 0) utils::logmesg(f.lmp, line);
  }

  void warn(const std::string &message) override
  {
    if (f.comm->me == 0) f.error->warning(FLERR, message);
  }

  int frozen_bits = 0;
  std::string frozen_by;

  void fail(const std::string &message) override
  {
    f.stop(FLERR, message);
  }

private:
  FixReinforceInvert &f;
  double saved_cutghostuser = 0;
  bool raised = false;
  bool binned = false;        // source-built: bins set up for a raised cutoff
  std::vector<int> row;       // source-built: list row of each owned atom
  double query_cutoff = 0;    // source-built: neighbours() gives atoms this close
};

/* ---------------------------------------------------------------------- */

FixReinforceInvert::FixReinforceInvert(LAMMPS *lmp, int narg, char **arg)
    : Fix(lmp, narg, arg), parsed(new reinforce::FixOptions), options(*parsed),
      totals(reinforce::kOutputSize, 0.0)
{
  std::vector<std::string> args;
  for (int i = 3; i < narg; ++i) args.emplace_back(arg[i]);
  try {
    options = reinforce::parse_fix_arguments(args);
  } catch (const reinforce::OptionError &e) {
    stop(FLERR, std::string(e.what()));
  }

  check_styles();
  find_groups_and_region();

  vector_flag = 1;
  size_vector = reinforce::kOutputSize;
  global_freq = 1;
  extvector = 0;
  comm_forward = 1;
  maxexchange = 1;
  create_attribute = 1;
  if (options.every > 0) {
    force_reneighbor = 1;
    next_reneighbor = -1;
  }

  grow_arrays(atom->nmax);
  atom->add_callback(Atom::GROW);
}

/* ---------------------------------------------------------------------- */

FixReinforceInvert::~FixReinforceInvert()
{
  if (copymode) return;
  atom->delete_callback(id, Atom::GROW);
}

bool FixReinforceInvert::done() const
{
  return invoked && options.every <= 0;
}

/* ---------------------------------------------------------------------- */

int FixReinforceInvert::setmask()
{
  // PRE_EXCHANGE also for N = 0: LAMMPS calls setup_pre_exchange() only for
  // fixes in its pre_exchange list. MIN_PRE_EXCHANGE: the same at a minimize.
  return PRE_EXCHANGE | MIN_PRE_EXCHANGE;
}

/* ---------------------------------------------------------------------- */

void FixReinforceInvert::check_styles()
{
  const std::string me = "Fix reinforce/invert ";
  if (!atom->radius_flag || !atom->rmass_flag)
    stop(FLERR, me + "requires atom attributes radius and rmass");
  if (!atom->tag_enable) stop(FLERR, me + "requires atom IDs");
  if (atom->molecular != Atom::ATOMIC) stop(FLERR, me + "does not support molecular atom styles");
  if (atom->ellipsoid_flag || atom->line_flag || atom->tri_flag || atom->body_flag)
    stop(FLERR, me + "does not support atom styles with bonus data (ellipsoid, line, tri, body)");
  if (domain->dimension != 3) stop(FLERR, me + "requires a 3d simulation");
  if (domain->triclinic) stop(FLERR, me + "does not support triclinic boxes");
  if (comm->style != 0) stop(FLERR, me + "requires comm_style brick");
  if (comm->mode != Comm::SINGLE) stop(FLERR, me + "requires comm_modify mode single");
  // Ghosts of one group only would hide neighbours from the relocation.
  if (CommAccess::border_group_of(comm) != 0)
    stop(FLERR, me + "does not support comm_modify group");
}

void FixReinforceInvert::find_groups_and_region()
{
  rebar_group = group->find(options.rebar_group);
  if (rebar_group < 0)
    stop(FLERR, "Fix reinforce/invert rebar group '" + options.rebar_group + "' does not exist");
  if (rebar_group == igroup)
    stop(FLERR, std::string("Fix reinforce/invert rebar group must differ from the fix group"));
  // A dynamic group is evaluated by its fix during the run's setup, after
  // the relocation: refused rather than read half-evaluated.
  if (group->dynamic[rebar_group])
    stop(FLERR, "Fix reinforce/invert rebar group '" + options.rebar_group +
                    "' is dynamic: make it static first (group " + options.rebar_group +
                    " static)");
  rebar_bit = group->bitmask[rebar_group];

  region = nullptr;
  if (!options.region.empty()) {
    region = find_region(domain, options.region);
    if (!region) stop(FLERR, "Fix reinforce/invert region '" + options.region + "' does not exist");
  }
}

// The fix moves and deletes single spheres: a matrix atom (fix group, not
// A LAMMPS built with exceptions (source builds) leaves the ERROR line in
// rank 0's log buffer when error->all throws; the other ranks may exit
// first, and mpirun then kills rank 0 before the buffer reaches the file.
// Rank 0 flushes before the exception leaves, and the others wait for it at
// the barrier of LAMMPS's main on their way out. (The packaged LAMMPS closes
// its files and exits inside error->all.)
void FixReinforceInvert::stop(const char *file, int line, const std::string &message)
{
  try {
    error->all(file, line, message);
  } catch (...) {
    if (comm->me == 0) {
      if (screen) fflush(screen);
      if (logfile) fflush(logfile);
    }
    throw;
  }
}

// rebar) in the group of a rigid-body fix (rigid, rigid/small, ...) would
// be torn out of its body. Bars may be rigid bodies. Collective.
void FixReinforceInvert::check_rigid_bodies()
{
  for (int ifix = 0; ifix < modify->nfix; ++ifix) {
    const Fix *other = modify->fix[ifix];
    if (std::strncmp(other->style, "rigid", 5) != 0) continue;
    int mine = 0, any = 0;
    for (int i = 0; i < atom->nlocal && !mine; ++i)
      mine = (atom->mask[i] & groupbit) && !(atom->mask[i] & rebar_bit) &&
             (atom->mask[i] & other->groupbit);
    MPI_Allreduce(&mine, &any, 1, MPI_INT, MPI_MAX, world);
    if (any)
      stop(FLERR, std::string("Fix reinforce/invert cannot move atoms of rigid bodies: "
                              "matrix atoms belong to fix ") +
                      other->id + " (" + other->style + "); leave the bodies out of the fix group");
  }
}

// True when an atom of `other`'s group is a matrix atom of this fix (fix
// group, not rebar), on any process. Collective.
bool FixReinforceInvert::shares_matrix_atoms(const Fix *other)
{
  int mine = 0, any = 0;
  for (int i = 0; i < atom->nlocal && !mine; ++i)
    mine = (atom->mask[i] & groupbit) && !(atom->mask[i] & rebar_bit) &&
           (atom->mask[i] & other->groupbit);
  MPI_Allreduce(&mine, &any, 1, MPI_INT, MPI_MAX, world);
  return any != 0;
}

// A wall fix keeps its geometry in protected members (and Debian's LAMMPS
// ships no header of any wall fix): the fix cannot see it, so a relocated
// sphere could be put through the wall and lost in the next run. Unless
// the user gives a region that holds the matrix, or accepts the risk, the
// run stops here. fix wall/flow makes no wall. Collective.
void FixReinforceInvert::check_walls()
{
  if (options.walls_ignore) return;
  std::string skipped;
  for (int ifix = 0; ifix < modify->nfix; ++ifix) {
    const Fix *other = modify->fix[ifix];
    if (std::strncmp(other->style, "wall/", 5) != 0 || std::strcmp(other->style, "wall/flow") == 0)
      continue;
    if (!shares_matrix_atoms(other)) continue;
    const std::string which = std::string("fix ") + other->id + " (" + other->style + ")";
    if (!region)
      stop(FLERR, "Fix reinforce/invert cannot see the walls of " + which +
                      ": give a region that holds the matrix (region keyword: whole spheres "
                      "are kept inside it) or walls ignore");
    skipped += "; " + which + " not read: region " + options.region + " holds the matrix";
  }
  if (!skipped.empty() && comm->me == 0)
    utils::logmesg(lmp, "fix reinforce/invert: walls: none read" + skipped + "\n");
}

// The rebar of the other reinforce/invert fixes: never moved by this one.
void FixReinforceInvert::find_other_rebar(int &bits, std::string &names)
{
  bits = 0;
  names.clear();
  int count = 0;
  for (int ifix = 0; ifix < modify->nfix; ++ifix) {
    const auto *other = dynamic_cast<const FixReinforceInvert *>(modify->fix[ifix]);
    if (!other || other == this || other->rebar_bit == rebar_bit) continue;
    bits |= other->rebar_bit;
    names += (count++ ? ", " : "") + std::string(other->id);
  }
  if (count) names = (count > 1 ? "fixes " : "fix ") + names;
}

/* ---------------------------------------------------------------------- */

void FixReinforceInvert::init()
{
  // N = 0 and done: nothing it could check matters any more, and nothing
  // about it may stop a later run (its groups or region may be gone).
  if (done()) return;
  // Styles, groups and regions may have changed since the fix was defined.
  check_styles();
  find_groups_and_region();
#if REINFORCE_LAMMPS_SOURCE_BUILD
  // [2] Occasional: built only inside an invocation (Host::build_neighbour_lists).
  request_neighbour_list();
#endif
}

#if REINFORCE_LAMMPS_SOURCE_BUILD
// [2] An occasional full list at the reach of matrix-rebar contact: the
// largest matrix radius (fix group, not rebar) plus the largest rebar
// radius, over all processes, 1% more (rounding; radii that grow a little
// during the run), and with the radius keyword room for relocated spheres
// up to its rmax, as far as the communication cutoff allows. Only the
// overlap check that finds the targets uses it (docs/design.md, "Targets").
// No list (the engine's grid instead, same targets) with a neighbor style
// other than bin (LAMMPS honours a list's own cutoff only there) or when
// contact reaches past the communication cutoff: LAMMPS stops the run at
// init for a custom cutoff beyond it ("Custom neighbor list cutoff too large
// for communication cutoff"), and the ghost cutoff raised during an
// invocation comes too late for a list set up at init. Collective.
void FixReinforceInvert::request_neighbour_list()
{
  constexpr double kListMargin = 0.01;
  list_cutoff = 0;
  list_used = -1;
  double mine[2] = {0.0, 0.0}, all[2] = {0.0, 0.0};    // matrix, rebar
  for (int i = 0; i < atom->nlocal; ++i) {
    if (atom->mask[i] & rebar_bit)
      mine[1] = std::max(mine[1], atom->radius[i]);
    else if (atom->mask[i] & groupbit)
      mine[0] = std::max(mine[0], atom->radius[i]);
  }
  MPI_Allreduce(mine, all, 2, MPI_DOUBLE, MPI_MAX, world);
  const double contact = all[0] + all[1];
  const double matrix_r = options.radius_set ? std::max(all[0], options.rmax) : all[0];
  const double wanted = (matrix_r + all[1]) * (1 + kListMargin);
  // Neighbor::init() and Comm::init() run after the fixes' init(): their
  // cutoffs as they will compute them. cutneighmax: the largest pair cutoff
  // plus skin (Neighbor::init, the same expression); the communication
  // cutoff: the larger of it and comm_modify cutoff (Comm::get_comm_cutoff;
  // no bonds here, the fix refuses molecular styles).
  double cutneighmax = 0;
  if (force->pair && force->pair->cutsq)
    for (int i = 1; i <= atom->ntypes; ++i)
      for (int j = 1; j <= atom->ntypes; ++j) {
        const double cut = std::sqrt(force->pair->cutsq[i][j]);
        if (cut > 0.0) cutneighmax = std::max(cutneighmax, cut + neighbor->skin);
      }
  const double comm_cutoff = std::max(comm->cutghostuser, cutneighmax);
  double cutoff = std::min(wanted, comm_cutoff);
  // A request at exactly cutneighmax is turned into the default list (with
  // per-type cutoffs); just below it, it keeps its own.
  if (cutoff == cutneighmax) cutoff = std::nextafter(cutoff, 0.0);
  // `list` is set by init_list() when LAMMPS makes the lists anew; when
  // every request is as in the previous run it keeps them and does not call
  // init_list(): the pointer from then is still the list. Without a request
  // it is dropped (LAMMPS deletes the old lists).
  NeighList *const kept = list;
  list = nullptr;
  if (neighbor->style != Neighbor::BIN) {
    list_why = "LAMMPS's neighbor style is not bin";
  } else if (!(contact > 0.0)) {
    list_why = "no matrix or rebar atom at the start of the run";
  } else if (!(cutoff >= contact)) {
    list_why = "the matrix-rebar contact " + format_length(contact) +
               " exceeds LAMMPS's communication cutoff " + format_length(comm_cutoff) +
               " (pair cutoff + skin, or comm_modify cutoff)";
  } else {
    list = kept;
    list_why.clear();
    list_cutoff = cutoff;
    set_fixed_cutoff(neighbor->add_request(this, NeighConst::REQ_FULL | NeighConst::REQ_OCCASIONAL),
                     list_cutoff, 0);
  }
}

void FixReinforceInvert::init_list(int /*id*/, NeighList *ptr)
{
  list = ptr;
}
#endif

/* ---------------------------------------------------------------------- */

void FixReinforceInvert::setup_pre_exchange()
{
  // write_restart and write_data also call setup_pre_exchange (whichflag 0):
  // only a run or a minimization relocates.
  if (update->whichflag == 0 || done()) return;
  setup_seen = true;
  if (options.every > 0) next_reneighbor = (update->ntimestep / options.every + 1) * options.every;
  if (invoked) return;
  invoked = true;
  invoke();
}

// A run with "pre no" skips init and setup (LAMMPS calls only
// output->setup), but every run ends with post_run() of every fix: there the
// fix says it did not relocate.
void FixReinforceInvert::post_run()
{
  if (!invoked && !setup_seen && comm->me == 0)
    error->warning(FLERR, std::string("Fix reinforce/invert did not relocate: the setup of this "
                                      "run was skipped (run pre no); it relocates at the setup "
                                      "of a run with pre yes"));
  setup_seen = false;
}

void FixReinforceInvert::pre_exchange()
{
  if (options.every <= 0 || next_reneighbor != update->ntimestep) return;
  next_reneighbor += options.every;
  invoke();
}

/* ---------------------------------------------------------------------- */

void FixReinforceInvert::invoke()
{
  if (static_cast<int>(pending.size()) < atom->nmax) grow_arrays(atom->nmax);
  std::fill(pending.begin(), pending.end(), kPresent);
  if (region) region->prematch();
  check_rigid_bodies();
  check_walls();

  Host host(*this);
  find_other_rebar(host.frozen_bits, host.frozen_by);
  anchored.clear();
  for (int ifix = 0; ifix < modify->nfix; ++ifix)
    if (std::strcmp(modify->fix[ifix]->style, "spring/self") == 0) anchored.emplace_back(ifix, 0.0);
  const reinforce::Totals t = reinforce::run_invocation(host, options);
  for (const auto &[ifix, count] : anchored) {
    const double moved = host.sum(count);
    if (moved > 0 && comm->me == 0)
      error->warning(FLERR, "Fix reinforce/invert moved " + format_count(moved) +
                                " atoms held by fix " + modify->fix[ifix]->id +
                                " (spring/self): their anchors are still the old positions");
  }

  // Atoms marked in the last round are deleted by one more refresh. Then, as
  // delete_atoms does, the global count and the map of atom IDs. natoms is
  // decreased by the deletions rather than recounted, so that atoms lost in
  // any other way are still reported by LAMMPS.
  if (t.deleted > 0) {
    host.refresh();
    atom->natoms -= static_cast<bigint>(t.deleted);
    if (atom->map_style != Atom::MAP_NONE) {
      atom->map_init();
      atom->map_set();
    }
  }
  // Nothing stale: every flag is clear between invocations.
  std::fill(pending.begin(), pending.end(), kPresent);

  const auto out = reinforce::output_vector(t);
  totals.assign(out.begin(), out.end());
}

/* ---------------------------------------------------------------------- */

double FixReinforceInvert::compute_vector(int n)
{
  return (n >= 0 && n < reinforce::kOutputSize) ? totals[n] : 0.0;
}

/* ---------------------------------------------------------------------- */

void FixReinforceInvert::grow_arrays(int nmax)
{
  if (static_cast<int>(pending.size()) < nmax) pending.resize(nmax, 0);
}

void FixReinforceInvert::copy_arrays(int i, int j, int /*delflag*/)
{
  pending[j] = pending[i];
}

void FixReinforceInvert::set_arrays(int i)
{
  pending[i] = 0;
}

int FixReinforceInvert::pack_exchange(int i, double *buf)
{
  buf[0] = pending[i];
  return 1;
}

int FixReinforceInvert::unpack_exchange(int nlocal, double *buf)
{
  pending[nlocal] = static_cast<int>(buf[0]);
  return 1;
}

int FixReinforceInvert::pack_forward_comm(int n, int *list, double *buf, int /*pbc_flag*/,
                                          int * /*pbc*/)
{
  for (int k = 0; k < n; ++k) buf[k] = pending[list[k]];
  return n;
}

void FixReinforceInvert::unpack_forward_comm(int n, int first, double *buf)
{
  for (int k = 0; k < n; ++k) pending[first + k] = static_cast<int>(buf[k]);
}

double FixReinforceInvert::memory_usage()
{
  return static_cast<double>(pending.capacity() * sizeof(int));
}
