#include "mpi_work_queue.hpp"

#include <mpi.h>

#include <chrono>
#include <cstdint>

namespace peristep::host {

namespace {
constexpr int kRequestTag = 1501, kReplyTag = 1502;
}

MpiWorkQueue::MpiWorkQueue(const MpiSession& session, std::size_t total) : session_(session), total_(total) {
  if (session_.rank() == 0 && session_.size() > 1) server_ = std::thread([this] { serve(); });
}

MpiWorkQueue::~MpiWorkQueue() {
  stop_ = true;
  if (server_.joinable()) server_.join();
}

void MpiWorkQueue::serve() {
  int told = 0;  // ranks told that the level is done
  while (told < session_.size() - 1 && !stop_) {
    int arrived = 0;
    MPI_Status status;
    MPI_Iprobe(MPI_ANY_SOURCE, kRequestTag, MPI_COMM_WORLD, &arrived, &status);
    if (!arrived) {  // polling with a pause: a blocking receive would spin a core at 100%
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
      continue;
    }
    MPI_Recv(nullptr, 0, MPI_BYTE, status.MPI_SOURCE, kRequestTag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    std::uint64_t index = counter_.fetch_add(1);
    if (index >= total_) {
      index = total_;
      ++told;
    }
    MPI_Send(&index, 1, MPI_UINT64_T, status.MPI_SOURCE, kReplyTag, MPI_COMM_WORLD);
  }
}

std::optional<std::size_t> MpiWorkQueue::next() {
  if (session_.rank() == 0) {
    const std::size_t index = counter_.fetch_add(1);
    return index < total_ ? std::optional<std::size_t>(index) : std::nullopt;
  }
  if (done_) return std::nullopt;
  std::uint64_t index = 0;
  MPI_Send(nullptr, 0, MPI_BYTE, 0, kRequestTag, MPI_COMM_WORLD);
  MPI_Recv(&index, 1, MPI_UINT64_T, 0, kReplyTag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  done_ = index >= total_;
  return done_ ? std::nullopt : std::optional<std::size_t>(index);
}

void MpiWorkQueue::finish() {
  if (server_.joinable()) server_.join();
}

}  // namespace peristep::host
