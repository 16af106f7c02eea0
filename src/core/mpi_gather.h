// One MPI collective both host adapters need (the core itself never calls
// MPI: run_invocation reaches it through HostHooks::gather_all).
#pragma once

#include <mpi.h>

#include <vector>

namespace reinforce {

// Every rank's values, concatenated in rank order.
inline std::vector<double> mpi_gather_all(const std::vector<double> &mine, MPI_Comm comm)
{
  int nprocs = 1;
  MPI_Comm_size(comm, &nprocs);
  const int count = static_cast<int>(mine.size());
  std::vector<int> counts(nprocs), offsets(nprocs, 0);
  MPI_Allgather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, comm);
  for (int p = 1; p < nprocs; ++p) offsets[p] = offsets[p - 1] + counts[p - 1];
  std::vector<double> all(offsets.back() + counts.back());
  MPI_Allgatherv(mine.data(), count, MPI_DOUBLE, all.data(), counts.data(), offsets.data(),
                 MPI_DOUBLE, comm);
  return all;
}

}    // namespace reinforce
