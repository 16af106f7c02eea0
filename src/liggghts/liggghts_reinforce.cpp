// liggghts_reinforce: Debian's liggghts with fix reinforce/invert added.
// Same command line and behaviour as liggghts.
#include "input.h"
#include "lammps.h"
#include "register_style.h"

#include <mpi.h>

int main(int argc, char **argv)
{
  MPI_Init(&argc, &argv);
  auto *lmp = new LAMMPS_NS::LAMMPS(argc, argv, MPI_COMM_WORLD);
  register_reinforce_invert(lmp);
  lmp->input->file();
  delete lmp;
  MPI_Finalize();
  return 0;
}
