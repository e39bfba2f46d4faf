#pragma once
// Dynamic scheduling of one level's job indices over the MPI ranks (samples differ 10x in cost, so a
// static split would idle ranks). Rank 0 holds the counter; a thread on rank 0 answers the other ranks'
// requests (one message each way per sample) while rank 0's main thread runs samples too, taking its
// indices from the same atomic counter. Every rank asks for the next index when it is free.
// Why not a shared counter by MPI one-sided (MPI_Fetch_and_op on a window): passive-target operations
// are only guaranteed to progress when the target rank enters MPI (Open MPI 4.1 without RDMA atomics,
// e.g. over TCP, emulates them by messages), and rank 0 spends minutes to hours inside the component;
// the thread answers within a millisecond whatever rank 0 is doing.
#include <atomic>
#include <cstddef>
#include <optional>
#include <thread>

#include "mpi_session.hpp"

namespace peristep::host {

class MpiWorkQueue {
 public:
  MpiWorkQueue(const MpiSession& session, std::size_t total);
  ~MpiWorkQueue();  // joins rank 0's thread
  MpiWorkQueue(const MpiWorkQueue&) = delete;
  MpiWorkQueue& operator=(const MpiWorkQueue&) = delete;

  // The next index for this rank, or nothing once all are handed out.
  std::optional<std::size_t> next();
  // Rank 0: waits until every other rank has been told the level is done. Then rank 0 may call MPI again.
  void finish();

 private:
  void serve();

  const MpiSession& session_;
  std::size_t total_;
  std::atomic<std::size_t> counter_{0};  // rank 0
  std::atomic<bool> stop_{false};        // rank 0: leave without waiting (an error unwinds)
  std::thread server_;                   // rank 0
  bool done_ = false;                    // other ranks
};

}  // namespace peristep::host
