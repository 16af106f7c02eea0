// fix reinforce/invert: what LAMMPS does its own way (fix_reinforce_invert.h);
// the fix itself is ReinforceFixBase (src/host).
//
// Messages: only the std::string overloads of error->all() and
// utils::logmesg() link against Debian's LAMMPS (see fmt_compat/fmt/format.h),
// so every message is built as a std::string.
//
// REINFORCE_LAMMPS_SOURCE_BUILD (fix_reinforce_invert.h): a LAMMPS built
// from source offers the fix an occasional full neighbour list
// (neigh_request.h), which Debian's package does not ship; and it renamed
// NeighRequest::set_cutoff to set_cutoff_fixed in August 2026.

#if __cplusplus < 201703L
#error "fix reinforce/invert needs C++17: -D CMAKE_CXX_STANDARD=17 (LAMMPS before 22Jul2025)"
#endif

#include "fix_reinforce_invert.h"

#include "atom.h"
#include "comm.h"
#include "group.h"
#if REINFORCE_LAMMPS_SOURCE_BUILD
#include "force.h"
#include "neigh_list.h"
#include "neigh_request.h"
#include "neighbor.h"
#include "pair.h"
#endif

#include "reinforce_fix_options.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>

using namespace LAMMPS_NS;

namespace {

// Comm keeps bordergroup protected. A class derived from it may name the
// member through a pointer to member; no object of this class is made.
struct CommAccess : Comm {
  static int border_group_of(const Comm *c) { return c->*(&CommAccess::bordergroup); }
};

#if REINFORCE_LAMMPS_SOURCE_BUILD
std::string format_length(double v)
{
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", v);
  return text;
}

// One cutoff for every type pair: NeighRequest::set_cutoff_fixed since
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

}    // namespace

FixReinforceInvert::FixReinforceInvert(LAMMPS *lmp, int narg, char **arg)
    : ReinforceFixBase(lmp, narg, arg)
{
  maxexchange = 1;
  check_setup();
}

void FixReinforceInvert::check_host()
{
  const std::string me = "Fix reinforce/invert ";
  if (comm->style != 0) fail(FLERR, me + "requires comm_style brick");
  if (comm->mode != Comm::SINGLE) fail(FLERR, me + "requires comm_modify mode single");
  // Ghosts of one group only would hide neighbours from the relocation.
  if (CommAccess::border_group_of(comm) != 0)
    fail(FLERR, me + "does not support comm_modify group");
  // A dynamic group is evaluated by its fix during the run's setup, after
  // the relocation: refused rather than read half-evaluated.
  if (group->dynamic[rebar_group])
    fail(FLERR, me + "rebar group '" + options.rebar_group +
                    "' is dynamic: make it static first (group " + options.rebar_group +
                    " static)");
}

// fix rigid, rigid/small, rigid/nve, ...: every atom of the fix's group is
// in one of its bodies.
bool FixReinforceInvert::in_body(Fix &other, int i)
{
  return std::strncmp(other.style, "rigid", 5) == 0 && (atom->mask[i] & other.groupbit);
}

// LAMMPS expects the number of values sent back.
int FixReinforceInvert::pack_forward_comm(int n, int *list, double *buf, int pbc_flag, int *pbc)
{
  return n * pack_forward(n, list, buf, pbc_flag, pbc);
}

void FixReinforceInvert::unpack_forward_comm(int n, int first, double *buf)
{
  unpack_forward(n, first, buf);
}

#if REINFORCE_LAMMPS_SOURCE_BUILD
void FixReinforceInvert::init()
{
  ReinforceFixBase::init();
  // Occasional: built only inside an invocation (build_neighbour_lists).
  if (!done()) request_neighbour_list();
}

// An occasional full list at the reach of matrix-rebar contact: the
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

// The list for the overlap check that finds the targets (HostHooks).
// Rows for owned atoms only (LAMMPS refuses an occasional binned list with
// ghost info), their neighbours owned or ghost: what neighbours()
// promises, and all that check needs. Its cutoff was fixed at init(): a
// larger request (radii grew since), exclusions, or no list at all are
// answered "no list", and the engine uses its own grid (same targets).
//
// Built as delete_atoms builds its list after a fresh exchange: bins for
// the current ghost extent (raised or not), neighbor->build(), then
// build_one(). build() is needed: the refresh moved atoms after LAMMPS last
// binned them, and only build() bins them again (build_one() does not);
// and build_one() skips a list built since the last build(), and every
// list before the first build() of all (at the first run's setup: both
// step stamps are -1; tests/source_hosts, *_host_list_*, fail without
// it). The perpetual lists build() makes too are made again by LAMMPS
// right after pre_exchange, as after fix gcmc and fix atom/swap, which
// also call neighbor->build() there.
bool FixReinforceInvert::build_neighbour_lists(double cutoff)
{
  const double ghost = std::min({comm->cutghost[0], comm->cutghost[1], comm->cutghost[2]});
  std::string why;
  if (!list)
    why = list_why.empty() ? "LAMMPS gave the fix no list" : list_why;
  else if (neighbor->exclude || neighbor->includegroup)
    why = "neigh_modify exclude or include is set (the list would leave pairs out)";
  else if (!(cutoff <= list_cutoff))
    why = "the matrix-rebar contact " + format_length(cutoff) + " exceeds the list's cutoff " +
          format_length(list_cutoff) + " (radii grew since the run began)";
  else if (!(list_cutoff <= ghost))
    why = "the ghost cutoff " + format_length(ghost) + " is shorter than the list's cutoff";
  const int used = why.empty() ? 1 : 0;
  if (used != list_used)
    log(used ? "fix reinforce/invert: targets found with LAMMPS's occasional full neighbor list "
               "(cutoff " +
                   format_length(list_cutoff) + ")\n"
             : "fix reinforce/invert: targets found with the engine's grid: " + why + "\n");
  list_used = used;
  if (!used) return false;

  neighbor->setup_bins();    // bins for the current ghost extent
  binned = true;
  neighbor->build(1);
  neighbor->build_one(list);
  row.assign(atom->nlocal, -1);
  for (int ii = 0; ii < list->inum; ++ii)
    if (list->ilist[ii] < atom->nlocal) row[list->ilist[ii]] = ii;
  query_cutoff = cutoff;
  return true;
}

void FixReinforceInvert::neighbours(int local, std::vector<int> &out)
{
  out.clear();
  if (local < 0 || local >= static_cast<int>(row.size()) || row[local] < 0) return;
  const int i = list->ilist[row[local]];
  const int *jlist = list->firstneigh[i];
  const double *xi = atom->x[i];
  for (int k = 0; k < list->numneigh[i]; ++k) {
    const int j = jlist[k] & NEIGHMASK;
    const double dx = xi[0] - atom->x[j][0], dy = xi[1] - atom->x[j][1], dz = xi[2] - atom->x[j][2];
    if (dx * dx + dy * dy + dz * dz <= query_cutoff * query_cutoff) out.push_back(j);
  }
}

// Back to the run's ghost extent.
void FixReinforceInvert::ghost_cutoff_restored()
{
  if (binned) neighbor->setup_bins();
  binned = false;
}
#endif
