// fix reinforce/invert: what LIGGGHTS does its own way (fix_reinforce_invert.h);
// the fix itself is ReinforceFixBase (src/host).

#include "fix_reinforce_invert.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "fix_multisphere.h"
#include "fix_wall_gran.h"
#include "neighbor.h"
#include "region.h"

#include "reinforce_liggghts_walls.h"

#include "reinforce_fix_options.h"

#include <cstring>

using namespace LAMMPS_NS;

namespace {

// Comm keeps style and bordergroup protected. A class derived from it may
// name them through a pointer to member; no object of this class is made.
struct CommAccess : Comm {
  static int style_of(const Comm *c) { return c->*(&CommAccess::style); }
  static int border_group_of(const Comm *c) { return c->*(&CommAccess::bordergroup); }
};

}    // namespace

FixReinforceInvert::FixReinforceInvert(LAMMPS *lmp, int narg, char **arg)
    : ReinforceFixBase(lmp, narg, arg), walls(new LiggghtsWalls)
{
  check_setup();
}

FixReinforceInvert::~FixReinforceInvert() = default;

// LIGGGHTS calls min_setup_pre_exchange, not setup_pre_exchange, for the
// fixes that ask for MIN_PRE_EXCHANGE at a minimization: PRE_EXCHANGE only.
int FixReinforceInvert::setmask()
{
  return FixConst::PRE_EXCHANGE;
}

// communicate multi ignores the raised ghost cutoff, and ghosts of one
// group only would hide neighbours: both would leave overlaps.
void FixReinforceInvert::check_host()
{
  if (CommAccess::style_of(comm) != 0)
    fail(FLERR, "Fix reinforce/invert requires communicate single");
  if (CommAccess::border_group_of(comm) != 0)
    fail(FLERR, "Fix reinforce/invert does not support communicate group");
}

// Whole spheres are kept inside the region by its surface distance
// (Host::placement_domain), which these regions do not have.
void FixReinforceInvert::check_region(Region &region)
{
  if (std::strcmp(region.style, "mesh/tet") == 0 ||
      (std::strcmp(region.style, "wedge") == 0 && !region.interior))
    fail(FLERR, "Fix reinforce/invert region '" + options.region + "' (" + region.style +
                    (region.interior ? "" : ", side out") +
                    ") has no surface distance: whole spheres cannot be kept inside it");
}

bool FixReinforceInvert::in_body(Fix &other, int i)
{
  return std::strncmp(other.style, "multisphere", 11) == 0 &&
         static_cast<FixMultisphere &>(other).belongs_to(i) >= 0;
}

// The meshes and primitive walls of fix wall/gran; any other wall fix is
// one the fix cannot see.
std::string FixReinforceInvert::read_walls(Fix &wall)
{
  auto *gran = dynamic_cast<FixWallGran *>(&wall);
  return gran ? walls->read(*gran, world) : "";
}

void FixReinforceInvert::forget_walls()
{
  walls->clear();
}

std::shared_ptr<const reinforce::Boundaries> FixReinforceInvert::walls_in_view()
{
  const double reach[3] = {ghost_reach(0), ghost_reach(1), ghost_reach(2)};
  return walls->in_view(*domain, reach);
}

// LIGGGHTS's granular optimisation (Comm::use_gran_opt, inline in comm_I.h,
// on for every orthogonal box whose atoms have a radius) acquires ghosts
// only within half the ghost cutoff plus half the skin.
bool FixReinforceInvert::granular_ghosts() const
{
  return domain->triclinic == 0 && atom->radius != nullptr;
}

double FixReinforceInvert::ghost_reach(int d)
{
  return granular_ghosts() ? 0.5 * (comm->cutghost[d] + neighbor->skin) : comm->cutghost[d];
}

double FixReinforceInvert::ghost_cutoff_for(double reach)
{
  return granular_ghosts() ? 2 * reach : reach;
}

// LIGGGHTS expects the number of values per atom back.
int FixReinforceInvert::pack_comm(int n, int *list, double *buf, int pbc_flag, int *pbc)
{
  return pack_forward(n, list, buf, pbc_flag, pbc);
}

void FixReinforceInvert::unpack_comm(int n, int first, double *buf)
{
  unpack_forward(n, first, buf);
}
