#include "mpi_session.hpp"

#include <mpi.h>

#include <cstdlib>
#include <iostream>

#include "host_errors.hpp"

namespace peristep::host {

bool launchedByMpi() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK"})
    if (std::getenv(name)) return true;
  return false;
}

MpiSession::MpiSession() {
  if (!launchedByMpi()) return;
  int provided = 0;
  if (MPI_Init_thread(nullptr, nullptr, MPI_THREAD_SERIALIZED, &provided) != MPI_SUCCESS)
    throw RunError("MPI_Init_thread failed");
  initialized_ = true;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
  if (provided < MPI_THREAD_SERIALIZED && size_ > 1)
    abort("the MPI library does not provide MPI_THREAD_SERIALIZED, which the sample scheduler needs", kExitRunError);
}

MpiSession::~MpiSession() {
  if (initialized_) MPI_Finalize();
}

std::uint64_t MpiSession::sumToRoot(std::uint64_t value) const {
  if (size_ == 1) return value;
  std::uint64_t sum = 0;
  MPI_Reduce(&value, &sum, 1, MPI_UINT64_T, MPI_SUM, 0, MPI_COMM_WORLD);
  return sum;
}

void MpiSession::broadcast(std::vector<std::uint64_t>& values) const {
  if (size_ == 1) return;
  std::uint64_t count = values.size();
  MPI_Bcast(&count, 1, MPI_UINT64_T, 0, MPI_COMM_WORLD);
  values.resize(count);
  MPI_Bcast(values.data(), static_cast<int>(count), MPI_UINT64_T, 0, MPI_COMM_WORLD);
}

void MpiSession::abort(const std::string& message, int exitCode) const {
  std::cerr << "peristep (rank " << rank_ << " of " << size_ << "): " << message << std::endl;
  MPI_Abort(MPI_COMM_WORLD, exitCode);
  std::_Exit(exitCode);  // MPI_Abort does not return; this line keeps [[noreturn]] true if it did
}

}  // namespace peristep::host
