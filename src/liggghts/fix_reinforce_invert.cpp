#include "fix_reinforce_invert.h"

#include "atom.h"
#include "atom_vec.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix_multisphere.h"
#include "group.h"
#include "memory.h"
#include "neighbor.h"
#include "modify.h"
#include "region.h"
#include "update.h"

#include "mpi_gather.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>

using namespace LAMMPS_NS;

namespace {

// Comm keeps style and bordergroup protected. A class derived from it may
// name them through a pointer to member; no object of this class is made.
struct CommAccess : Comm {
  static int style_of(const Comm *c) { return c->*(&CommAccess::style); }
  static int border_group_of(const Comm *c) { return c->*(&CommAccess::bordergroup); }
};

}    // namespace

FixReinforceInvert::FixReinforceInvert(LAMMPS *lmp, int narg, char **arg) : Fix(lmp, narg, arg)
{
  try {
    options_ = reinforce::parse_fix_arguments(std::vector<std::string>(arg + 3, arg + narg));
  } catch (const reinforce::OptionError &e) {
    error->all(FLERR, e.what());
  }
  const int rebar = group->find(options_.rebar_group.c_str());
  if (rebar < 0)
    fail("Fix reinforce/invert rebar group '" + options_.rebar_group + "' does not exist");
  if (rebar == igroup) fail("Fix reinforce/invert rebar group must differ from the fix group");
  rebar_bit_ = group->bitmask[rebar];
  if (!atom->radius_flag || !atom->rmass_flag)
    fail("Fix reinforce/invert requires atom attributes radius and rmass");
  if (atom->molecular) fail("Fix reinforce/invert does not support molecular atom styles");
  if (domain->triclinic) fail("Fix reinforce/invert does not support triclinic boxes");
  if (domain->dimension != 3) fail("Fix reinforce/invert requires a 3d simulation");
  if (!options_.region.empty()) {
    const int r = domain->find_region(const_cast<char *>(options_.region.c_str()));
    if (r < 0) fail("Fix reinforce/invert region '" + options_.region + "' does not exist");
  }

  vector_flag = 1;
  size_vector = reinforce::kOutputSize;
  global_freq = 1;
  extvector = 0;
  comm_forward = 1;
  if (options_.every > 0) force_reneighbor = 1;
  next_reneighbor = -1;

  grow_arrays(atom->nmax);
  atom->add_callback(0);
}

FixReinforceInvert::~FixReinforceInvert()
{
  atom->delete_callback(id, 0);
  memory->destroy(pending_);
}

// PRE_EXCHANGE also for N = 0: the host calls setup_pre_exchange only for
// fixes that ask for pre_exchange.
int FixReinforceInvert::setmask()
{
  return FixConst::PRE_EXCHANGE;
}

void FixReinforceInvert::init()
{
  // N = 0 and done: nothing it could check matters any more, and nothing
  // about it may stop a later run (its region may be gone).
  if (invoked_ && options_.every <= 0) return;
  if (domain->triclinic) fail("Fix reinforce/invert does not support triclinic boxes");
  // communicate multi ignores the raised ghost cutoff, and ghosts of one
  // group only would hide neighbours: both would leave overlaps.
  if (CommAccess::style_of(comm) != 0) fail("Fix reinforce/invert requires communicate single");
  if (CommAccess::border_group_of(comm) != 0)
    fail("Fix reinforce/invert does not support communicate group");
  region_ = nullptr;
  if (!options_.region.empty()) {
    const int r = domain->find_region(const_cast<char *>(options_.region.c_str()));
    if (r < 0) fail("Fix reinforce/invert region '" + options_.region + "' does not exist");
    region_ = domain->regions[r];
  }
}

// Once at the setup of the first run (or minimization) that follows; with
// N > 0 also every N steps. write_restart and write_data call setup too
// (whichflag 0): they never relocate.
void FixReinforceInvert::setup_pre_exchange()
{
  if (update->whichflag == 0) return;
  if (options_.every > 0)
    next_reneighbor = (update->ntimestep / options_.every + 1) * options_.every;
  if (!invoked_) invoke();
}

void FixReinforceInvert::pre_exchange()
{
  if (options_.every <= 0 || update->ntimestep != next_reneighbor) return;
  next_reneighbor += options_.every;
  invoke();
}

void FixReinforceInvert::invoke()
{
  invoked_ = true;
  // Atoms created since the last invocation (insert/pack, create_atoms)
  // carry no flag yet: every flag starts clear.
  std::fill(pending_, pending_ + nmax_, 0);
  if (region_) region_->prematch();
  check_multisphere_bodies();
  // A raised ghost cutoff is put back on every way out, also when an error
  // unwinds through the invocation (a host built to throw).
  struct RestoreGhostCutoff {
    FixReinforceInvert *fix;
    ~RestoreGhostCutoff() { fix->restore_ghost_cutoff(); }
  } restore{this};
  exchange_.reset(new reinforce::MpiExchange(world));
  const reinforce::Totals t = reinforce::run_invocation(*this, options_);
  exchange_.reset();
  output_ = reinforce::output_vector(t);
  // As delete_atoms does: the global count and the atom map.
  bigint nlocal = atom->nlocal;
  MPI_Allreduce(&nlocal, &atom->natoms, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  if (atom->map_style) {
    atom->nghost = 0;
    atom->map_init();
    atom->map_set();
  }
}

// The fix moves and deletes single spheres: a matrix sphere (fix group, not
// rebar) that belongs to a body of fix multisphere would be torn out of it.
// Bars may be multisphere bodies. Collective.
void FixReinforceInvert::check_multisphere_bodies()
{
  for (int ifix = 0; ifix < modify->nfix; ++ifix) {
    if (std::strncmp(modify->fix[ifix]->style, "multisphere", 11) != 0) continue;
    const FixMultisphere *ms = static_cast<FixMultisphere *>(modify->fix[ifix]);
    int mine = 0, any = 0;
    for (int i = 0; i < atom->nlocal && !mine; ++i)
      mine = (atom->mask[i] & groupbit) && !(atom->mask[i] & rebar_bit_) && ms->belongs_to(i) >= 0;
    MPI_Allreduce(&mine, &any, 1, MPI_INT, MPI_MAX, world);
    if (any)
      fail(
          std::string("Fix reinforce/invert cannot move atoms of rigid bodies: matrix atoms belong "
                      "to fix ") +
          modify->fix[ifix]->id + " (" + modify->fix[ifix]->style +
          "); leave the bodies out of the fix group");
  }
}

double FixReinforceInvert::compute_vector(int n)
{
  return (n >= 0 && n < reinforce::kOutputSize) ? output_[n] : 0.0;
}

/* ---- per-atom pending flag ---- */

void FixReinforceInvert::grow_arrays(int nmax)
{
  const int old = pending_ ? nmax_ : 0;
  memory->grow(pending_, nmax, "reinforce/invert:pending");
  std::fill(pending_ + old, pending_ + std::max(old, nmax), 0);
  nmax_ = nmax;
}

void FixReinforceInvert::copy_arrays(int i, int j, int)
{
  pending_[j] = pending_[i];
}

int FixReinforceInvert::pack_exchange(int i, double *buf)
{
  buf[0] = pending_[i];
  return 1;
}

int FixReinforceInvert::unpack_exchange(int nlocal, double *buf)
{
  pending_[nlocal] = static_cast<int>(buf[0]);
  return 1;
}

// LIGGGHTS 3.8 expects the number of values per atom back (LAMMPS 2021's
// pack_forward_comm returns the total).
int FixReinforceInvert::pack_comm(int n, int *list, double *buf, int, int *)
{
  for (int k = 0; k < n; ++k) buf[k] = pending_[list[k]];
  return 1;
}

void FixReinforceInvert::unpack_comm(int n, int first, double *buf)
{
  for (int k = 0; k < n; ++k) pending_[first + k] = static_cast<int>(buf[k]);
}

/* ---- reinforce::HostHooks ---- */

void FixReinforceInvert::refresh()
{
  domain->pbc();
  domain->reset_box();
  comm->setup();
  comm->exchange();
  atom->nghost = 0;
  comm->borders();
  forward_pending();
}

reinforce::AtomArrays FixReinforceInvert::atoms()
{
  reinforce::AtomArrays a;
  a.nlocal = atom->nlocal;
  a.nall = atom->nlocal + atom->nghost;
  a.x = atom->x;
  a.radius = atom->radius;
  a.tag.assign(atom->tag, atom->tag + a.nall);
  a.mask = atom->mask;
  a.pending = pending_;
  a.group_bit = groupbit;
  a.rebar_bit = rebar_bit_;
  return a;
}

void FixReinforceInvert::set_pending(int local, bool pending)
{
  pending_[local] = pending ? 1 : 0;
}

void FixReinforceInvert::forward_pending()
{
  comm->forward_comm_fix(this);
}

// LIGGGHTS's granular optimisation (Comm::use_gran_opt, inline in comm_I.h,
// on for every orthogonal box whose atoms have a radius) acquires ghosts
// only within half the ghost cutoff plus half the skin.
bool FixReinforceInvert::granular_ghosts()
{
  return domain->triclinic == 0 && atom->radius != nullptr;
}

// How far ghost atoms reach beyond the subdomain in dimension d.
double FixReinforceInvert::ghost_reach(int d)
{
  return granular_ghosts() ? 0.5 * (comm->cutghost[d] + neighbor->skin) : comm->cutghost[d];
}

void FixReinforceInvert::ensure_ghost_cutoff(double reach)
{
  const double have = std::min({ghost_reach(0), ghost_reach(1), ghost_reach(2)});
  if (have >= reach) return;
  user_cutghost_ = comm->cutghostuser;
  comm->cutghostuser = granular_ghosts() ? 2 * reach : reach;
  refresh();
  char line[200];
  std::snprintf(line, sizeof line,
                "fix reinforce/invert: ghost cutoff raised from %g to %g for the relocation\n",
                have, reach);
  log(line);
}

void FixReinforceInvert::restore_ghost_cutoff()
{
  if (user_cutghost_ < 0) return;
  comm->cutghostuser = user_cutghost_;
  user_cutghost_ = -1;
  comm->setup();
}

reinforce::Domain FixReinforceInvert::placement_domain()
{
  reinforce::Domain d;
  for (int k = 0; k < 3; ++k) {
    d.lo[k] = domain->boxlo[k];
    d.hi[k] = domain->boxhi[k];
    d.periodic[k] = domain->periodicity[k] != 0;
    d.view_lo[k] = domain->sublo[k] - ghost_reach(k);
    d.view_hi[k] = domain->subhi[k] + ghost_reach(k);
    d.sub_lo[k] = domain->sublo[k];
    d.sub_hi[k] = domain->subhi[k];
  }
  if (region_) {
    Region *region = region_;
    d.region = [region](const reinforce::Vec3 &c) { return region->match(c.x, c.y, c.z) != 0; };
  }
  return d;
}

void FixReinforceInvert::move(int i, reinforce::Vec3 x, double r)
{
  const double scale = r / atom->radius[i];
  for (int k = 0; k < 3; ++k) {
    atom->x[i][k] = x[k];
    atom->v[i][k] = 0;
    if (atom->omega_flag) atom->omega[i][k] = 0;
  }
  atom->rmass[i] *= scale * scale * scale;    // same material density
  atom->radius[i] = r;
  pending_[i] = 0;
}

// As delete_atoms does: the last owned atom moves into each hole (avec->copy
// also carries every fix's per-atom data). Highest index first, so a moved
// atom is never one still to be removed.
void FixReinforceInvert::remove(std::vector<int> &locals)
{
  std::sort(locals.rbegin(), locals.rend());
  for (int i : locals) {
    atom->avec->copy(atom->nlocal - 1, i, 1);
    atom->nlocal--;
  }
}

double FixReinforceInvert::sum(double v)
{
  double out;
  MPI_Allreduce(&v, &out, 1, MPI_DOUBLE, MPI_SUM, world);
  return out;
}

std::vector<double> FixReinforceInvert::gather_all(const std::vector<double> &mine)
{
  return reinforce::mpi_gather_all(mine, world);
}

void FixReinforceInvert::post_results(const std::vector<double> &mine,
                                      const std::vector<int> &ranks)
{
  exchange_->post(mine, ranks);
}

std::vector<double> FixReinforceInvert::collect_results(const std::vector<int> &ranks)
{
  return exchange_->collect(ranks);
}

void FixReinforceInvert::finish_results()
{
  exchange_->finish();
}

double FixReinforceInvert::max(double v)
{
  double out;
  MPI_Allreduce(&v, &out, 1, MPI_DOUBLE, MPI_MAX, world);
  return out;
}

double FixReinforceInvert::wall_time()
{
  return MPI_Wtime();
}

void FixReinforceInvert::log(const std::string &line)
{
  if (comm->me != 0) return;
  if (screen) std::fputs(line.c_str(), screen);
  if (logfile) std::fputs(line.c_str(), logfile);
}

void FixReinforceInvert::fail(const std::string &message)
{
  error->all(FLERR, message.c_str());
}
