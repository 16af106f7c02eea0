// lmp_reinforce: a drop-in for Debian's `lmp` (same command line, serially or
// under mpirun) that knows fix reinforce/invert. It runs the packaged LAMMPS
// library; the style is registered in Modify::fix_map (public in LAMMPS
// 2021) before the input is read, since this LAMMPS has no plugin command.

#include "fix_reinforce_invert.h"

#include "input.h"
#include "lammps.h"
#include "modify.h"

#include <mpi.h>

using namespace LAMMPS_NS;

namespace {

Fix *create_fix_reinforce_invert(LAMMPS *lmp, int narg, char **arg)
{
  return new FixReinforceInvert(lmp, narg, arg);
}

}    // namespace

int main(int argc, char **argv)
{
  MPI_Init(&argc, &argv);

  // This LAMMPS is built without LAMMPS_EXCEPTIONS: an ERROR finalizes MPI
  // and exits inside the library, as it does for the stock lmp.
  auto *lmp = new LAMMPS(argc, argv, MPI_COMM_WORLD);
  (*lmp->modify->fix_map)["reinforce/invert"] = &create_fix_reinforce_invert;
  lmp->input->file();
  delete lmp;

  MPI_Barrier(MPI_COMM_WORLD);
  MPI_Finalize();
  return 0;
}
