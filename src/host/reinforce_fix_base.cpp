// fix reinforce/invert on a LAMMPS-family host: the fix's life in a run,
// its checks and its per-atom flag (reinforce_fix_base.h). The engine's
// host hooks are in reinforce_fix_host.cpp.

#if __cplusplus < 201703L
#error "fix reinforce/invert needs C++17: -D CMAKE_CXX_STANDARD=17 (LAMMPS before 22Jul2025)"
#endif

#include "reinforce_fix_base.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "group.h"
#include "modify.h"
#include "region.h"
#include "update.h"

#include "reinforce_fix_host.h"
#include "reinforce_host_api.h"

#include "reinforce_fix_options.h"
#include "reinforce_host_hooks.h"
#include "reinforce_invocation.h"

#include <algorithm>
#include <cstdio>
#include <cstring>

using namespace LAMMPS_NS;
using Mark = reinforce::PendingFlags;

ReinforceFixBase::ReinforceFixBase(LAMMPS *lmp, int narg, char **arg)
    : Fix(lmp, narg, arg), parsed(new reinforce::FixOptions), options(*parsed),
      totals(reinforce::kOutputSize, 0.0)
{
  try {
    options = reinforce::parse_fix_arguments(std::vector<std::string>(arg + 3, arg + narg));
  } catch (const reinforce::OptionError &e) {
    fail(FLERR, e.what());
  }
  vector_flag = 1;
  size_vector = reinforce::kOutputSize;
  global_freq = 1;
  extvector = 0;
  comm_forward = reinforce::kForwardWidth;
  create_attribute = 1;
  if (options.every > 0) force_reneighbor = 1;
  next_reneighbor = -1;
  grow_arrays(atom->nmax);
  atom->add_callback(0);    // Atom::GROW on every host
}

ReinforceFixBase::~ReinforceFixBase()
{
  atom->delete_callback(id, 0);
}

bool ReinforceFixBase::done() const
{
  return invoked && options.every <= 0;
}

// PRE_EXCHANGE also for N = 0: the host calls setup_pre_exchange() only for
// fixes in its pre_exchange list. MIN_PRE_EXCHANGE: the same at a minimize.
int ReinforceFixBase::setmask()
{
  return FixConst::PRE_EXCHANGE | FixConst::MIN_PRE_EXCHANGE;
}

/* ---- checks ---- */

void ReinforceFixBase::check_setup()
{
  const std::string me = "Fix reinforce/invert ";
  if (!atom->radius_flag || !atom->rmass_flag)
    fail(FLERR, me + "requires atom attributes radius and rmass");
  if (!atom->tag_enable) fail(FLERR, me + "requires atom IDs");
  if (atom->molecular != 0) fail(FLERR, me + "does not support molecular atom styles");
  if (atom->ellipsoid_flag || atom->line_flag || atom->tri_flag || atom->body_flag)
    fail(FLERR, me + "does not support atom styles with bonus data (ellipsoid, line, tri, body)");
  if (domain->dimension != 3) fail(FLERR, me + "requires a 3d simulation");
  if (domain->triclinic) fail(FLERR, me + "does not support triclinic boxes");

  rebar_group = group->find(options.rebar_group.c_str());
  if (rebar_group < 0) fail(FLERR, me + "rebar group '" + options.rebar_group + "' does not exist");
  if (rebar_group == igroup) fail(FLERR, me + "rebar group must differ from the fix group");
  rebar_bit = group->bitmask[rebar_group];

  region = nullptr;
  if (!options.region.empty()) {
    region = reinforce::host_api::find_region(domain, options.region, 0);
    if (!region) fail(FLERR, me + "region '" + options.region + "' does not exist");
    check_region(*region);
  }
  check_host();
}

// True when an atom of `other`'s group is a matrix atom of this fix (fix
// group, not rebar), on any process: only those can be moved, so only
// fixes acting on them matter. Collective.
bool ReinforceFixBase::shares_matrix_atoms(const Fix &other)
{
  int mine = 0, any = 0;
  for (int i = 0; i < atom->nlocal && !mine; ++i)
    mine = (atom->mask[i] & groupbit) && !(atom->mask[i] & rebar_bit) &&
           (atom->mask[i] & other.groupbit);
  MPI_Allreduce(&mine, &any, 1, MPI_INT, MPI_MAX, world);
  return any != 0;
}

// The fix moves and deletes single spheres: a matrix atom in a rigid body
// (fix rigid in LAMMPS, fix multisphere in LIGGGHTS) would be torn out of
// it. Bars may be rigid bodies. Collective.
void ReinforceFixBase::check_bodies()
{
  for (int ifix = 0; ifix < modify->nfix; ++ifix) {
    Fix &other = *modify->fix[ifix];
    int mine = 0, any = 0;
    for (int i = 0; i < atom->nlocal && !mine; ++i)
      mine = (atom->mask[i] & groupbit) && !(atom->mask[i] & rebar_bit) && in_body(other, i);
    MPI_Allreduce(&mine, &any, 1, MPI_INT, MPI_MAX, world);
    if (any)
      fail(FLERR, std::string("Fix reinforce/invert cannot move atoms of rigid bodies: matrix "
                              "atoms belong to fix ") +
                      other.id + " (" + other.style + "); leave the bodies out of the fix group");
  }
}

std::string ReinforceFixBase::read_walls(Fix &)
{
  return "";
}

std::shared_ptr<const reinforce::Boundaries> ReinforceFixBase::walls_in_view()
{
  return nullptr;
}

// The walls of the wall fixes that act on the matrix, for the engine: what
// the host can read (read_walls) is honoured; a wall it cannot see stops
// the run, since a relocated sphere could be put through it, unless the
// region keyword holds the matrix or walls ignore is given. fix wall/flow
// (LAMMPS) makes no wall. Collective: every process reads the same fixes
// in the same order.
void ReinforceFixBase::check_walls()
{
  forget_walls();
  if (options.walls_ignore) return;
  std::string honoured, skipped;
  for (int ifix = 0; ifix < modify->nfix; ++ifix) {
    Fix &wall = *modify->fix[ifix];
    if (std::strncmp(wall.style, "wall/", 5) != 0 || std::strcmp(wall.style, "wall/flow") == 0)
      continue;
    if (!shares_matrix_atoms(wall)) continue;
    const std::string what = read_walls(wall);
    if (!what.empty()) {
      honoured += (honoured.empty() ? "" : ", ") + what + " of fix " + wall.id;
      continue;
    }
    const std::string which = std::string("fix ") + wall.id + " (" + wall.style + ")";
    if (!region)
      fail(FLERR, "Fix reinforce/invert cannot see the walls of " + which +
                      ": give a region that holds the matrix (region keyword: whole spheres "
                      "are kept inside it) or walls ignore");
    skipped += "; " + which + " not read: region " + options.region + " holds the matrix";
  }
  if (!honoured.empty() || !skipped.empty())
    log("fix reinforce/invert: walls: " + (honoured.empty() ? "none read" : honoured) + skipped +
        "\n");
}

// The rebar of the other reinforce/invert fixes (not sharing this one's
// bars): never moved by this one.
void ReinforceFixBase::find_other_rebar(int &bits, std::string &names)
{
  bits = 0;
  names.clear();
  int count = 0;
  for (int ifix = 0; ifix < modify->nfix; ++ifix) {
    const auto *other = dynamic_cast<const ReinforceFixBase *>(modify->fix[ifix]);
    if (!other || other == this || other->rebar_bit == rebar_bit) continue;
    bits |= other->rebar_bit;
    names += (count++ ? ", " : "") + std::string(other->id);
  }
  if (count) names = (count > 1 ? "fixes " : "fix ") + names;
}

// The fixes spring/self: a moved atom of their group stays tied to its old
// position, through whatever lies between (a bar).
void ReinforceFixBase::find_anchors()
{
  anchors.clear();
  for (int ifix = 0; ifix < modify->nfix; ++ifix)
    if (std::strcmp(modify->fix[ifix]->style, "spring/self") == 0)
      anchors.push_back({modify->fix[ifix]->id, modify->fix[ifix]->groupbit, {}});
}

// Each atom counted once, however often the invocation moved it. Collective.
void ReinforceFixBase::warn_anchors()
{
  for (const Anchors &a : anchors) {
    long long mine = static_cast<long long>(a.moved.size()), n = 0;
    MPI_Allreduce(&mine, &n, 1, MPI_LONG_LONG, MPI_SUM, world);
    if (n > 0)
      warn("Fix reinforce/invert moved " + std::to_string(n) + " atoms held by fix " + a.id +
           " (spring/self): their anchors are still the old positions");
  }
  anchors.clear();
}

/* ---- the run ---- */

void ReinforceFixBase::init()
{
  // N = 0 and done: nothing it could check matters any more, and nothing
  // about it may stop a later run (its groups or region may be gone).
  if (done()) return;
  // Styles, groups and regions may have changed since the fix was defined.
  check_setup();
}

void ReinforceFixBase::setup_pre_exchange()
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

void ReinforceFixBase::pre_exchange()
{
  if (options.every <= 0 || next_reneighbor != update->ntimestep) return;
  next_reneighbor += options.every;
  invoke();
}

// A run with "pre no" skips init and setup (the host calls no setup hook of
// any fix), but every run ends with post_run() of every fix: there the fix
// says it did not relocate.
void ReinforceFixBase::post_run()
{
  if (!invoked && !setup_seen)
    warn("Fix reinforce/invert did not relocate: the setup of this run was skipped (run pre no); "
         "it relocates at the setup of a run with pre yes");
  setup_seen = false;
  lost_matrix_warned = false;
}

void ReinforceFixBase::invoke()
{
  pending.grow(atom->nmax);
  // Atoms created since the last invocation carry no flag yet.
  pending.clear();
  if (region) region->prematch();
  check_bodies();
  check_walls();
  find_anchors();

  FixHost host(host_view());
  const reinforce::Totals t = reinforce::run_invocation(host, options);
  warn_anchors();
  // Once per run: with N > 0 every invocation would repeat it.
  const std::string lost =
      reinforce::regrowth_on(options)
          ? reinforce::lost_matrix_warning(t.stats, t.regrowth.jammed > 0)
          : "";
  if (!lost.empty() && !lost_matrix_warned) {
    warn(lost);
    lost_matrix_warned = true;
  }

  // Atoms removed in the last round leave with one more refresh (ghosts and
  // the atom map as they are now). The global count is lowered by the
  // deletions rather than recounted, as delete_atoms does, so that atoms
  // lost in any other way are still reported by the host.
  if (t.deleted > 0) {
    host.refresh();
    atom->natoms -= static_cast<bigint>(t.deleted);
    if (atom->map_style != 0) {
      atom->map_init();
      atom->map_set();
    }
  }
  pending.clear();
  const auto out = reinforce::output_vector(t);
  totals.assign(out.begin(), out.end());
}

// What the engine's host needs of this fix, and no more.
FixHostView ReinforceFixBase::host_view()
{
  FixHostView v;
  v.atom = atom;
  v.comm = comm;
  v.domain = domain;
  v.fix = this;
  v.world = world;
  v.pending = &pending;
  v.region = region;
  v.group_bit = groupbit;
  v.rebar_bit = rebar_bit;
  find_other_rebar(v.frozen_bits, v.frozen_by);
  v.ghost_reach = [this](int d) { return ghost_reach(d); };
  v.ghost_cutoff_for = [this](double reach) { return ghost_cutoff_for(reach); };
  v.ghost_cutoff_restored = [this] { ghost_cutoff_restored(); };
  v.walls_in_view = [this] { return walls_in_view(); };
  v.build_neighbour_lists = [this](double cutoff) { return build_neighbour_lists(cutoff); };
  v.neighbours = [this](int local, std::vector<int> &out) { neighbours(local, out); };
  v.forward = [this](std::vector<double> &values, int width, bool positions) {
    forward_values(values, width, positions);
  };
  v.moved = [this](int i) {
    for (Anchors &a : anchors)
      if (atom->mask[i] & a.bit) a.moved.insert(atom->tag[i]);
  };
  v.log = [this](const std::string &line) { log(line); };
  v.warn = [this](const std::string &message) { warn(message); };
  v.fail = [this](const std::string &message) { fail(FLERR, message); };
  return v;
}

double ReinforceFixBase::compute_vector(int n)
{
  return (n >= 0 && n < reinforce::kOutputSize) ? totals[n] : 0.0;
}

/* ---- messages ---- */

// A host built with exceptions (current LAMMPS) leaves the ERROR line in
// rank 0's log buffer when error->all throws; the other ranks may exit
// first, and mpirun then kills rank 0 before the buffer reaches the file.
// Rank 0 flushes before the exception leaves. (Debian's LAMMPS and
// LIGGGHTS close their files and exit inside error->all.)
void ReinforceFixBase::fail(const char *file, int line, const std::string &message)
{
  try {
    reinforce::host_api::error_all(error, file, line, message);
  } catch (...) {
    if (comm->me == 0) {
      if (screen) std::fflush(screen);
      if (logfile) std::fflush(logfile);
    }
    throw;
  }
}

void ReinforceFixBase::warn(const std::string &message)
{
  if (comm->me == 0) reinforce::host_api::warning(error, FLERR, message);
}

void ReinforceFixBase::log(const std::string &line)
{
  if (comm->me != 0) return;
  if (screen) std::fputs(line.c_str(), screen);
  if (logfile) std::fputs(line.c_str(), logfile);
}

/* ---- what a host may supply ---- */

double ReinforceFixBase::ghost_reach(int d)
{
  return comm->cutghost[d];
}

bool ReinforceFixBase::build_neighbour_lists(double)
{
  return false;
}

void ReinforceFixBase::neighbours(int, std::vector<int> &out)
{
  out.clear();
}

/* ---- the per-atom pending flag ---- */

void ReinforceFixBase::grow_arrays(int nmax)
{
  pending.grow(nmax);
}

void ReinforceFixBase::copy_arrays(int i, int j, int)
{
  pending[j] = pending[i];
}

void ReinforceFixBase::set_arrays(int i)
{
  pending[i] = Mark::kPresent;
}

int ReinforceFixBase::pack_exchange(int i, double *buf)
{
  buf[0] = pending[i];
  return 1;
}

int ReinforceFixBase::unpack_exchange(int nlocal, double *buf)
{
  pending[nlocal] = static_cast<int>(buf[0]);
  return 1;
}

// The forward communication sends the pending flags, or the rows of
// values the engine asked to send (forward_values): `width` per atom, the
// first three shifted by the box length for a periodic image when they are
// a position (as the host shifts its ghosts' coordinates). Returns the
// values per atom.
int ReinforceFixBase::pack_forward(int n, const int *list, double *buf, int pbc_flag,
                                   const int *pbc) const
{
  if (!rows) {
    for (int k = 0; k < n; ++k) buf[k] = pending[list[k]];
    return 1;
  }
  double shift[3] = {0, 0, 0};
  if (rows_are_positions && pbc_flag) {
    shift[0] = pbc[0] * domain->xprd;
    shift[1] = pbc[1] * domain->yprd;
    shift[2] = pbc[2] * domain->zprd;
  }
  for (int k = 0; k < n; ++k)
    for (int c = 0; c < row_width; ++c)
      buf[k * row_width + c] = rows[list[k] * row_width + c] + (c < 3 ? shift[c] : 0.0);
  return row_width;
}

void ReinforceFixBase::unpack_forward(int n, int first, const double *buf)
{
  if (!rows) {
    for (int k = 0; k < n; ++k) pending[first + k] = static_cast<int>(buf[k]);
    return;
  }
  std::copy(buf, buf + n * row_width, rows + first * row_width);
}

void ReinforceFixBase::forward_values(std::vector<double> &values, int width, bool positions)
{
  rows = values.data();
  row_width = width;
  rows_are_positions = positions;
  reinforce::host_api::forward_comm(comm, this, 0);
  rows = nullptr;
}

double ReinforceFixBase::memory_usage()
{
  return static_cast<double>(pending.bytes());
}
