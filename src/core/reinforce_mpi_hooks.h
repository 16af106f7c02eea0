// The MPI communication both host adapters need (the core itself never
// calls MPI: run_invocation reaches it through HostHooks), and the hooks
// made of it alone (MpiHooks), which both adapters' hosts derive from.
#pragma once

#include "reinforce_host_hooks.h"

#include <mpi.h>

#include <algorithm>

#include <utility>
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

// The rounds' results without a barrier (HostHooks::post_results and
// collect_results): post() sends this rank's values to the partner ranks
// and returns; collect() receives the partners' values of the oldest round
// posted and not yet collected, in rank order. A rank waits only for
// the ranks whose values are not there yet, and does its own work in the
// meantime. Messages between two ranks arrive in the order sent (MPI's
// non-overtaking rule), so one tag serves every round.
class MpiExchange {
public:
  explicit MpiExchange(MPI_Comm comm) : comm_(comm) { MPI_Comm_rank(comm, &rank_); }
  MpiExchange(const MpiExchange &) = delete;
  MpiExchange &operator=(const MpiExchange &) = delete;
  // Sends still under way (an error unwound through the rounds) may still
  // read their buffers: those are left allocated rather than freed under
  // MPI, and the requests released.
  ~MpiExchange()
  {
    for (Batch &b : sent_) {
      for (MPI_Request &r : b.requests)
        if (r != MPI_REQUEST_NULL) MPI_Request_free(&r);
      new std::vector<double>(std::move(b.values));    // deliberately kept
    }
  }

  void post(const std::vector<double> &mine, const std::vector<int> &ranks)
  {
    release_sent(false);
    sent_.push_back({mine, {}});
    Batch &b = sent_.back();
    const int count = static_cast<int>(b.values.size());
    for (int p : ranks) {
      if (p == rank_) continue;
      b.requests.emplace_back();
      MPI_Isend(b.values.data(), count, MPI_DOUBLE, p, kTag, comm_, &b.requests.back());
    }
  }

  std::vector<double> collect(const std::vector<int> &ranks)
  {
    std::vector<double> others;
    for (int p : ranks) {
      if (p == rank_) continue;
      MPI_Status status;
      MPI_Probe(p, kTag, comm_, &status);
      int count = 0;
      MPI_Get_count(&status, MPI_DOUBLE, &count);
      const std::size_t at = others.size();
      others.resize(at + static_cast<std::size_t>(count));
      MPI_Recv(others.data() + at, count, MPI_DOUBLE, p, kTag, comm_, MPI_STATUS_IGNORE);
    }
    return others;
  }

  // Waits until every posted value has been sent (after the last collect).
  void finish() { release_sent(true); }

private:
  static constexpr int kTag = 0x5249;    // "RI"
  struct Batch {
    std::vector<double> values;
    std::vector<MPI_Request> requests;
  };
  // Drops the batches whose sends are done (all of them, waiting, if `wait`).
  void release_sent(bool wait)
  {
    std::vector<Batch> pending;
    for (Batch &b : sent_) {
      int done = 1;
      const int n = static_cast<int>(b.requests.size());
      if (wait)
        MPI_Waitall(n, b.requests.data(), MPI_STATUSES_IGNORE);
      else
        MPI_Testall(n, b.requests.data(), &done, MPI_STATUSES_IGNORE);
      if (!done) pending.push_back(std::move(b));
    }
    sent_ = std::move(pending);
  }

  MPI_Comm comm_;
  int rank_ = 0;
  std::vector<Batch> sent_;
};

// The collective and timing hooks of a host on one MPI communicator: global
// sums, maxima and gathers, the rounds' point-to-point exchange (one
// exchange per host object: a host lives for one invocation) and the wall
// clock. The adapters add what touches their host's atoms.
class MpiHooks : public HostHooks {
public:
  explicit MpiHooks(MPI_Comm comm) : comm_(comm), exchange_(comm) {}

  double sum(double v) final { return reduce(v, MPI_SUM); }
  double max(double v) final { return reduce(v, MPI_MAX); }
  // One gather of both vectors; every rank adds and compares them in rank
  // order, so all get the same.
  void sum_and_max(std::vector<double> &sums, std::vector<double> &maxima) final
  {
    std::vector<double> mine(sums);
    mine.insert(mine.end(), maxima.begin(), maxima.end());
    int nprocs = 1;
    MPI_Comm_size(comm_, &nprocs);
    std::vector<double> all(mine.size() * static_cast<std::size_t>(nprocs));
    MPI_Allgather(mine.data(), static_cast<int>(mine.size()), MPI_DOUBLE, all.data(),
                  static_cast<int>(mine.size()), MPI_DOUBLE, comm_);
    std::fill(sums.begin(), sums.end(), 0.0);
    for (int p = 0; p < nprocs; ++p) {
      const double *theirs = &all[static_cast<std::size_t>(p) * mine.size()];
      for (std::size_t k = 0; k < sums.size(); ++k) sums[k] += theirs[k];
      for (std::size_t k = 0; k < maxima.size(); ++k)
        maxima[k] = std::max(maxima[k], theirs[sums.size() + k]);
    }
  }
  std::vector<double> gather_all(const std::vector<double> &mine) final
  {
    return mpi_gather_all(mine, comm_);
  }
  void post_results(const std::vector<double> &mine, const std::vector<int> &ranks) final
  {
    exchange_.post(mine, ranks);
  }
  std::vector<double> collect_results(const std::vector<int> &ranks) final
  {
    return exchange_.collect(ranks);
  }
  void finish_results() final { exchange_.finish(); }
  double wall_time() final { return MPI_Wtime(); }

private:
  double reduce(double v, MPI_Op op)
  {
    double out = 0;
    MPI_Allreduce(&v, &out, 1, MPI_DOUBLE, op, comm_);
    return out;
  }

  MPI_Comm comm_;
  MpiExchange exchange_;
};

}    // namespace reinforce
