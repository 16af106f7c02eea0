#include "fix_reinforce_invert.h"

#include "atom.h"
#include "atom_vec.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix_mesh_surface.h"
#include "fix_multisphere.h"
#include "fix_wall_gran.h"
#include "group.h"
#include "memory.h"
#include "neighbor.h"
#include "modify.h"
#include "primitive_wall_definitions.h"
#include "region.h"
#include "tri_mesh.h"
#include "update.h"

#include "reinforce_mpi_hooks.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <type_traits>

using namespace LAMMPS_NS;

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
    // Whole spheres are kept inside the region by its surface distance
    // (placement_domain), which these regions do not have.
    if (std::strcmp(region_->style, "mesh/tet") == 0 ||
        (std::strcmp(region_->style, "wedge") == 0 && !region_->interior))
      fail("Fix reinforce/invert region '" + options_.region + "' (" + region_->style +
           (region_->interior ? "" : ", side out") +
           ") has no surface distance: whole spheres cannot be kept inside it");
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

// run N pre no after an earlier run calls no setup hook on any fix (Run
// skips init and the integrator's setup, so neither setup_pre_exchange nor
// Modify::setup), and a fix added since the last init is in none of
// Modify's lists for the steps; Verlet::cleanup calls post_run on every
// fix after every run.
void FixReinforceInvert::post_run()
{
  if (!invoked_)
    warn("Fix reinforce/invert did not relocate: the setup of this run was skipped (run pre no); "
         "it relocates at the setup of a run with pre yes");
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

/* ---- walls and anchors ---- */

// The walls of the wall fixes that act on atoms of the fix group, for the
// engine (placement_domain): the meshes and primitive walls of fix
// wall/gran. Any other wall fix stops the run, its geometry being unknown
// here, unless the region keyword holds the matrix or walls ignore is
// given. Collective: every process reads the same fixes in the same order.
void FixReinforceInvert::read_walls()
{
  wall_planes_.clear();
  wall_cylinders_.clear();
  wall_triangles_.clear();
  walls_.reset();
  walls_margin_ = -1;
  if (options_.walls_ignore) return;
  std::string honoured, skipped;
  std::vector<const FixMeshSurface *> seen;    // a mesh of two wall fixes, once
  for (int k = 0; k < modify->nfix; ++k) {
    Fix *f = modify->fix[k];
    if (std::strncmp(f->style, "wall/", 5) != 0 || !shares_atoms(f->groupbit)) continue;
    auto *wall = dynamic_cast<FixWallGran *>(f);
    std::string what;
    if (wall && wall->is_mesh_wall()) {
      int meshes = 0, triangles = 0;
      for (int m = 0; m < wall->n_meshes(); ++m) {
        FixMeshSurface *mesh = wall->mesh_list()[m];
        if (std::find(seen.begin(), seen.end(), mesh) != seen.end()) continue;
        seen.push_back(mesh);
        triangles += add_mesh(*mesh);
        meshes++;
      }
      if (meshes > 0)
        what = std::to_string(meshes) + (meshes == 1 ? " mesh (" : " meshes (") +
               std::to_string(triangles) + " triangles)";
    } else if (wall && wall->primitiveWall()) {
      what = add_primitive_wall(*wall->primitiveWall());
      if (what.empty()) cannot_see_walls(*f, skipped);
    } else {
      cannot_see_walls(*f, skipped);
    }
    if (!what.empty()) honoured += (honoured.empty() ? "" : ", ") + what + " of fix " + f->id;
  }
  if (!honoured.empty() || !skipped.empty())
    log("fix reinforce/invert: walls: " + (honoured.empty() ? "none read" : honoured) + skipped +
        "\n");
}

// True when an atom of the fix group is in the group of `bit` (collective).
bool FixReinforceInvert::shares_atoms(int bit)
{
  int mine = 0, any = 0;
  for (int i = 0; i < atom->nlocal && !mine; ++i)
    mine = (atom->mask[i] & groupbit) && (atom->mask[i] & bit);
  MPI_Allreduce(&mine, &any, 1, MPI_INT, MPI_MAX, world);
  return any != 0;
}

// A wall fix whose geometry the adapter cannot read: with the region
// keyword the region keeps the spheres where the matrix is, and the wall is
// noted in the log line; else the run stops.
void FixReinforceInvert::cannot_see_walls(const Fix &wall, std::string &skipped)
{
  const std::string which = std::string("fix ") + wall.id + " (" + wall.style + ")";
  if (options_.region.empty())
    fail("Fix reinforce/invert cannot see the walls of " + which +
         ": give a region that holds the matrix (region keyword: whole spheres are kept inside "
         "it) or walls ignore");
  skipped += "; " + which + " not read: region " + options_.region + " holds the matrix";
}

// A primitive wall as a plane or cylinder, with its name for the log (empty
// when its type has no counterpart). The parameters, as
// primitive_wall_definitions.h uses them: a plane's position along its
// axis; a cylinder's radius, then its centre in the two other axes d + 1
// and d + 2 (mod 3): ycylinder R A B is centred at z = A, x = B.
std::string FixReinforceInvert::add_primitive_wall(const PrimitiveWall &wall)
{
  namespace walls = PRIMITIVE_WALL_DEFINITIONS;
  std::vector<double> p;
  const int type = primitive_wall_shape(wall, p);
  reinforce::Boundaries probe;    // refuses degenerate or non-finite walls
  if (type >= walls::XPLANE && type <= walls::ZPLANE && p.size() == 1) {
    const int d = type - walls::XPLANE;
    reinforce::Plane plane;
    plane.point[d] = p[0];
    plane.normal[d] = 1;
    if (!probe.add(plane)) return "";
    wall_planes_.push_back(plane);
  } else if (type >= walls::XCYLINDER && type <= walls::ZCYLINDER && p.size() == 3) {
    const int d = type - walls::XCYLINDER;
    reinforce::Cylinder cylinder;
    cylinder.axis[d] = 1;
    cylinder.point[(d + 1) % 3] = p[1];
    cylinder.point[(d + 2) % 3] = p[2];
    cylinder.radius = p[0];
    if (!probe.add(cylinder)) return "";
    wall_cylinders_.push_back(cylinder);
  } else {
    return "";
  }
  return std::string("1 primitive wall (") + walls::wallString[type] + ")";
}

// Every triangle of a mesh, the same complete set on every process; returns
// their number. Before the mesh's first setup (FixMesh::setup_pre_force,
// after this fix's setup_pre_exchange at the first run), and for a mesh
// that is never parallel, every process holds all the elements; afterwards
// each holds those it owns (the first sizeLocal) and ghost copies, and the
// owned ones of all processes are gathered. isParallel is the same on
// every process.
int FixReinforceInvert::add_mesh(FixMeshSurface &fix)
{
  TriMesh *mesh = fix.triMesh();
  std::vector<double> mine;
  mine.reserve(9 * static_cast<std::size_t>(mesh->sizeLocal()));
  for (int i = 0; i < mesh->sizeLocal(); ++i)
    for (int j = 0; j < 3; ++j) {
      double p[3];
      mesh->node(i, j, p);
      mine.insert(mine.end(), p, p + 3);
    }
  const std::vector<double> all =
      mesh->isParallel() ? reinforce::mpi_gather_all(mine, world) : mine;
  for (std::size_t k = 0; k + 9 <= all.size(); k += 9)
    wall_triangles_.push_back({{all[k], all[k + 1], all[k + 2]},
                               {all[k + 3], all[k + 4], all[k + 5]},
                               {all[k + 6], all[k + 7], all[k + 8]}});
  return static_cast<int>(all.size() / 9);
}

// The walls for the engine. In a periodic dimension the engine's
// coordinates reach beyond the box (ghost images, new centres next to
// them), and the walls must be there too: triangles get their images
// within twice the ghost reach of the box (which holds every sphere a
// process sees). Planes and cylinders are taken as they are. Built again
// only when that reach grows (the engine asks before and after raising the
// ghost cutoff); the same on every process.
std::shared_ptr<const reinforce::Boundaries> FixReinforceInvert::walls_in_view()
{
  if (wall_planes_.empty() && wall_cylinders_.empty() && wall_triangles_.empty()) return nullptr;
  double margin = 0;
  for (int d = 0; d < 3 && !wall_triangles_.empty(); ++d)
    if (domain->periodicity[d]) margin = std::max(margin, 2 * ghost_reach(d));
  if (walls_ && margin <= walls_margin_) return walls_;
  auto walls = std::make_shared<reinforce::Boundaries>();
  for (const reinforce::Plane &p : wall_planes_) walls->add(p);
  for (const reinforce::Cylinder &c : wall_cylinders_) walls->add(c);
  std::vector<reinforce::Triangle> all = wall_triangles_;
  for (int d = 0; d < 3 && margin > 0; ++d) {
    if (!domain->periodicity[d]) continue;
    const double length = domain->prd[d];
    const int shifts = static_cast<int>(std::ceil(margin / length));
    const std::size_t n = all.size();
    for (std::size_t t = 0; t < n; ++t)
      for (int s = -shifts; s <= shifts; ++s) {
        if (s == 0) continue;
        reinforce::Triangle image = all[t];
        for (reinforce::Vec3 *v : {&image.a, &image.b, &image.c}) (*v)[d] += s * length;
        const double lo = std::min({image.a[d], image.b[d], image.c[d]});
        const double hi = std::max({image.a[d], image.b[d], image.c[d]});
        if (hi >= domain->boxlo[d] - margin && lo <= domain->boxhi[d] + margin)
          all.push_back(image);
      }
  }
  for (const reinforce::Triangle &t : all) walls->add(t);
  walls_ = walls;
  walls_margin_ = margin;
  return walls_;
}

// The fixes spring/self: a moved atom of their group stays tied to its old
// position, through whatever lies between (a bar).
void FixReinforceInvert::find_anchors()
{
  anchors_.clear();
  for (int k = 0; k < modify->nfix; ++k)
    if (std::strcmp(modify->fix[k]->style, "spring/self") == 0)
      anchors_.push_back({modify->fix[k]->id, modify->fix[k]->groupbit, {}});
}

// Collective.
void FixReinforceInvert::warn_anchors()
{
  for (const Anchors &a : anchors_) {
    long long mine = static_cast<long long>(a.moved.size()), n = 0;
    MPI_Allreduce(&mine, &n, 1, MPI_LONG_LONG, MPI_SUM, world);
    if (n > 0)
      warn("Fix reinforce/invert moved " + std::to_string(n) + " atoms held by fix " + a.id +
           " (spring/self): their anchors are still the old positions");
  }
  anchors_.clear();
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

/* ---- the engine's host ---- */

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

void FixReinforceInvert::log(const std::string &line)
{
  if (comm->me != 0) return;
  if (screen) std::fputs(line.c_str(), screen);
  if (logfile) std::fputs(line.c_str(), logfile);
}

void FixReinforceInvert::warn(const std::string &message)
{
  if (comm->me == 0) error->warning(FLERR, message.c_str());
}

void FixReinforceInvert::fail(const std::string &message)
{
  error->all(FLERR, message.c_str());
}

// LIGGGHTS's atoms and communication behind reinforce::HostHooks (the MPI
// hooks are reinforce::MpiHooks, shared with the LAMMPS adapter), for one
// invocation. run_invocation() calls every collective hook on all
// processes; move() and remove() only on the processes of the current round.
class FixReinforceInvert::Host : public reinforce::MpiHooks {
public:
  explicit Host(FixReinforceInvert &fix) : MpiHooks(fix.world), f(fix) {}
  // A raised ghost cutoff is put back on every way out of the invocation,
  // also when an error unwinds through it (a host built to throw).
  ~Host() override { restore_ghost_cutoff(); }
  Host(const Host &) = delete;
  Host &operator=(const Host &) = delete;

  void refresh() override
  {
    f.domain->pbc();
    f.domain->reset_box();
    f.comm->setup();
    f.comm->exchange();
    f.atom->nghost = 0;
    f.comm->borders();
    forward_pending();
  }

  reinforce::AtomArrays atoms() override
  {
    Atom *atom = f.atom;
    reinforce::AtomArrays a;
    a.nlocal = atom->nlocal;
    a.nall = atom->nlocal + atom->nghost;
    a.x = atom->x;
    a.radius = atom->radius;
    set_ids(a, atom->tag);
    a.mask = atom->mask;
    a.pending = f.pending_;
    a.group_bit = f.groupbit;
    a.rebar_bit = f.rebar_bit_;
    // The bars of the other reinforce/invert fixes stay as they are.
    std::vector<std::string> others;
    for (int k = 0; k < f.modify->nfix; ++k) {
      Fix *other = f.modify->fix[k];
      if (other == &f || std::strcmp(other->style, "reinforce/invert") != 0) continue;
      a.frozen_bits |= static_cast<FixReinforceInvert *>(other)->rebar_bit_;
      others.push_back(other->id);
    }
    for (std::size_t k = 0; k < others.size(); ++k)
      a.frozen_by += (k == 0 ? (others.size() == 1 ? "fix " : "fixes ") : ", ") + others[k];
    return a;
  }

  void set_pending(int local, bool pending) override { f.pending_[local] = pending ? 1 : 0; }

  void forward_pending() override { f.comm->forward_comm_fix(&f); }

  reinforce::GhostCutoff ensure_ghost_cutoff(double reach) override
  {
    const double have = std::min({f.ghost_reach(0), f.ghost_reach(1), f.ghost_reach(2)});
    if (have >= reach) return {have, have, false};
    // A second raise (the regrowth) restores the user's value too.
    if (user_cutghost < 0) user_cutghost = f.comm->cutghostuser;
    f.comm->cutghostuser = f.granular_ghosts() ? 2 * reach : reach;
    refresh();
    return {have, reach, true};
  }

  void restore_ghost_cutoff() override
  {
    if (user_cutghost < 0) return;
    f.comm->cutghostuser = user_cutghost;
    user_cutghost = -1;
    f.comm->setup();
  }

  reinforce::Domain placement_domain() override
  {
    Domain *domain = f.domain;
    reinforce::Domain d;
    for (int k = 0; k < 3; ++k) {
      d.lo[k] = domain->boxlo[k];
      d.hi[k] = domain->boxhi[k];
      d.periodic[k] = domain->periodicity[k] != 0;
      d.view_lo[k] = domain->sublo[k] - f.ghost_reach(k);
      d.view_hi[k] = domain->subhi[k] + f.ghost_reach(k);
      d.sub_lo[k] = domain->sublo[k];
      d.sub_hi[k] = domain->subhi[k];
    }
    if (f.region_) {
      // match_shrinkby_cut(x, cut) is match(x) and no contact with the
      // region's surface closer than cut on the region's side: for side in
      // the centre is inside and surface_interior finds no face within cut,
      // for side out it is outside the shape and surface_exterior finds none
      // (the distances fix wall/region uses). Either way the ball of radius
      // cut lies wholly in the region. (region.h calls it "OR"; the code is
      // AND.) A moving region was set for this step by prematch in invoke.
      Region *region = f.region_;
      d.region = [region](const reinforce::Vec3 &c, double r) {
        double x[3] = {c.x, c.y, c.z};
        return region->match_shrinkby_cut(x, r) != 0;
      };
    }
    d.walls = f.walls_in_view();
    return d;
  }

  void move(int i, reinforce::Vec3 x, double r) override
  {
    Atom *atom = f.atom;
    const double scale = r / atom->radius[i];
    for (int k = 0; k < 3; ++k) {
      atom->x[i][k] = x[k];
      atom->v[i][k] = 0;
      if (atom->omega_flag) atom->omega[i][k] = 0;
    }
    atom->rmass[i] *= scale * scale * scale;    // same material density
    atom->radius[i] = r;
    f.pending_[i] = 0;
    for (Anchors &a : f.anchors_)
      if (atom->mask[i] & a.bit) a.moved.insert(atom->tag[i]);
  }

  // As delete_atoms does: the last owned atom moves into each hole
  // (avec->copy also carries every fix's per-atom data). Highest index
  // first, so a moved atom is never one still to be removed.
  void remove(std::vector<int> &locals) override
  {
    std::sort(locals.rbegin(), locals.rend());
    for (int i : locals) {
      f.atom->avec->copy(f.atom->nlocal - 1, i, 1);
      f.atom->nlocal--;
    }
  }

  void log(const std::string &line) override { f.log(line); }
  void warn(const std::string &message) override { f.warn(message); }
  void fail(const std::string &message) override { f.fail(message); }

private:
  FixReinforceInvert &f;
  double user_cutghost = -1;    // >= 0 while the ghost cutoff is raised
};

/* ---- the invocation ---- */

void FixReinforceInvert::invoke()
{
  invoked_ = true;
  // Atoms created since the last invocation (insert/pack, create_atoms)
  // carry no flag yet: every flag starts clear.
  std::fill(pending_, pending_ + nmax_, 0);
  if (region_) region_->prematch();
  check_multisphere_bodies();
  read_walls();
  find_anchors();
  reinforce::Totals t;
  {
    Host host(*this);
    t = reinforce::run_invocation(host, options_);
  }
  warn_anchors();
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
