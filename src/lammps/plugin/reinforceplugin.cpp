// reinforceplugin.so: fix reinforce/invert for a LAMMPS built from source
// with the PLUGIN package (`plugin load reinforceplugin.so`, or a directory
// named in LAMMPS_PLUGIN_PATH). The fix itself is ../fix_reinforce_invert.cpp,
// compiled for this path with REINFORCE_LAMMPS_SOURCE_BUILD=1 (README, "Use
// with your own LAMMPS").

#include "lammpsplugin.h"
#include "version.h"

#include "fix_reinforce_invert.h"

using namespace LAMMPS_NS;

namespace {

Fix *create_fix_reinforce_invert(LAMMPS *lmp, int narg, char **arg)
{
  return new FixReinforceInvert(lmp, narg, arg);
}

}    // namespace

extern "C" void lammpsplugin_init(void *lmp, void *handle, void *regfunc)
{
  lammpsplugin_t plugin;
  auto register_plugin = (lammpsplugin_regfunc)regfunc;

  plugin.version = LAMMPS_VERSION;
  plugin.style = "fix";
  plugin.name = "reinforce/invert";
  plugin.info = "fix reinforce/invert: relocates matrix spheres overlapping reinforcement bars";
  plugin.author = "reinforce/invert project";
  plugin.creator.v2 = (lammpsplugin_factory2 *)&create_fix_reinforce_invert;
  plugin.handle = handle;
  (*register_plugin)(&plugin, lmp);
}
