// The cost of one round's exchange of results (reinforce::MpiExchange, as
// the adapters use it) against the number of partners, for the model of
// larger runs in docs/benchmarks.md. Run on 2 processes: k partners are k
// messages to the other process and k from it per round, each of a
// round's typical size; every round is a post then a collect, as in the fix.
// Prints "partners<TAB>microseconds per round" (median of batches) on rank 0.
//
// usage: mpirun -np 2 exchange_cost [doubles per message] [rounds per batch] [batches]
#include "reinforce_mpi_hooks.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <vector>

int main(int argc, char **argv)
{
  MPI_Init(&argc, &argv);
  int rank = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  if (size != 2) {
    if (rank == 0) std::fprintf(stderr, "exchange_cost: run it on 2 processes\n");
    MPI_Finalize();
    return 1;
  }
  // A round of the beam at 0.60: about 30 targets per process, 6 doubles each.
  const int doubles = argc > 1 ? std::atoi(argv[1]) : 180;
  const int rounds = argc > 2 ? std::atoi(argv[2]) : 500;
  const int batches = argc > 3 ? std::atoi(argv[3]) : 9;
  const std::vector<double> mine(static_cast<std::size_t>(std::max(doubles, 0)), 1.0 * rank);
  double sink = 0;
  for (int partners : {1, 2, 4, 8, 16, 26}) {
    const std::vector<int> ranks(static_cast<std::size_t>(partners), 1 - rank);
    std::vector<double> per_round;
    for (int b = 0; b < batches; ++b) {
      reinforce::MpiExchange exchange(MPI_COMM_WORLD);
      MPI_Barrier(MPI_COMM_WORLD);
      const double start = MPI_Wtime();
      for (int r = 0; r < rounds; ++r) {
        exchange.post(mine, ranks);
        const std::vector<double> others = exchange.collect(ranks);
        sink += others.empty() ? 0 : others.back();
      }
      exchange.finish();
      per_round.push_back((MPI_Wtime() - start) / rounds);
    }
    std::sort(per_round.begin(), per_round.end());
    if (rank == 0) std::printf("%d\t%.3f\n", partners, 1e6 * per_round[per_round.size() / 2]);
  }
  if (sink < 0) std::printf("%g\n", sink);    // keeps the received values live
  MPI_Finalize();
  return 0;
}
