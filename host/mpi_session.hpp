#pragma once
// MPI for `peristep sample`, only when the process was started by an MPI launcher (mpirun, mpiexec,
// srun): without one the program neither initializes MPI nor needs a launcher, and runs as one rank.
#include <cstdint>
#include <string>
#include <vector>

namespace peristep::host {

// True when the environment holds an MPI launcher's rank variables (Open MPI, PMI, PMIx).
bool launchedByMpi();

class MpiSession {
 public:
  // MPI_Init_thread with MPI_THREAD_SERIALIZED (rank 0's scheduler thread calls MPI while its main
  // thread does not) when launchedByMpi(); otherwise rank 0 of 1. RunError when the library cannot.
  MpiSession();
  ~MpiSession();  // MPI_Finalize
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;

  int rank() const { return rank_; }
  int size() const { return size_; }
  // Sum over the ranks, valid on rank 0.
  std::uint64_t sumToRoot(std::uint64_t value) const;
  // Rank 0's values on every rank (the other ranks' vectors are resized to match).
  void broadcast(std::vector<std::uint64_t>& values) const;
  // Prints the message with this rank's number and ends every rank (the others would wait forever).
  [[noreturn]] void abort(const std::string& message, int exitCode) const;

 private:
  bool initialized_ = false;
  int rank_ = 0, size_ = 1;
};

}  // namespace peristep::host
