// A ghost cutoff the fix raised is put back when an ERROR
// unwinds through the relocation. LAMMPS built from source throws its
// errors (LAMMPSException), so a program that runs LAMMPS as a library goes
// on after one; its next run must not keep the raised cutoff.
//
//   error_restores_cutoff PLUGIN.so SCENE.data
//
// The error comes from a region style made here whose match() stops with an
// ERROR: the fix tests placements against it while the cutoff is raised.
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "exceptions.h"
#include "input.h"
#include "lammps.h"
#include "region.h"

#include <mpi.h>

#include <cstdio>
#include <string>

using namespace LAMMPS_NS;

namespace {

class RegionThrowing : public Region {
public:
  RegionThrowing(LAMMPS *lmp, int narg, char **arg) : Region(lmp, narg, arg)
  {
    options(narg - 2, &arg[2]);
  }
  int inside(double, double, double) override
  {
    error->all(FLERR, "region throwing: an error inside the relocation");
    return 0;
  }
  int surface_interior(double *, double) override { return 0; }
  int surface_exterior(double *, double) override { return 0; }
};

Region *create_region(LAMMPS *lmp, int narg, char **arg)
{
  return new RegionThrowing(lmp, narg, arg);
}

}    // namespace

int main(int argc, char **argv)
{
  if (argc != 3) {
    std::fprintf(stderr, "usage: error_restores_cutoff PLUGIN.so SCENE.data\n");
    return 2;
  }
  MPI_Init(&argc, &argv);
  const char *lmpargs[] = {"lmp", "-log", "none", "-screen", "none", nullptr};
  auto *lmp = new LAMMPS(5, const_cast<char **>(lmpargs), MPI_COMM_WORLD);
  (*lmp->domain->region_map)["throwing"] = &create_region;
  const std::string commands[] = {"plugin load " + std::string(argv[1]),
                                  "units si",
                                  "atom_style sphere",
                                  "atom_modify map array",
                                  "read_data " + std::string(argv[2]),
                                  "group rebar type 2",
                                  "neighbor 0 bin",
                                  "region bad throwing",
                                  "fix r all reinforce/invert 0 rebar region bad"};
  int status = 1;
  try {
    for (const std::string &c : commands) lmp->input->one(c);
    const double before = lmp->comm->cutghostuser;
    std::string message;
    try {
      lmp->input->one("run 0");
    } catch (LAMMPSException &e) {
      message = e.what();
    }
    const double after = lmp->comm->cutghostuser;
    std::printf(
        "error: %s\nghost cutoff (comm_modify cutoff) before the run %g, after the error %g\n",
        message.c_str(), before, after);
    if (message.find("an error inside the relocation") == std::string::npos)
      std::printf("FAIL: the run did not stop with the region's error\n");
    else if (after != before)
      std::printf("FAIL: the raised ghost cutoff was left in place\n");
    else {
      std::printf("PASS: the ghost cutoff is restored after an error\n");
      status = 0;
    }
  } catch (LAMMPSException &e) {
    std::printf("FAIL: setting up: %s\n", e.what());
  }
  delete lmp;
  MPI_Finalize();
  return status;
}
