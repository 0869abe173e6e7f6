#include "distributed/mpi_link.h"

#include <algorithm>
#include <chrono>
#include <thread>
#include <vector>

namespace rt {
namespace {

constexpr uint64_t kChunkBytes = 1ull << 30;

}  // namespace

MPI_Status wait_for(int source, int tag) {
  MPI_Status status;
  for (int flag = 0;;) {
    MPI_Iprobe(source, tag, MPI_COMM_WORLD, &flag, &status);
    if (flag) return status;
    std::this_thread::sleep_for(std::chrono::microseconds(500));
  }
}

void send_bytes(const void* data, uint64_t bytes, int rank, int tag) {
  const char* p = static_cast<const char*>(data);
  do {
    const uint64_t n = std::min(bytes, kChunkBytes);
    MPI_Send(p, static_cast<int>(n), MPI_BYTE, rank, tag, MPI_COMM_WORLD);
    p += n;
    bytes -= n;
  } while (bytes > 0);
}

void recv_bytes(void* data, uint64_t bytes, int rank, int tag) {
  char* p = static_cast<char*>(data);
  do {
    const uint64_t n = std::min(bytes, kChunkBytes);
    wait_for(rank, tag);
    MPI_Recv(p, static_cast<int>(n), MPI_BYTE, rank, tag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    p += n;
    bytes -= n;
  } while (bytes > 0);
}

void send_text(const std::string& text, int rank, int tag) {
  MPI_Send(text.data(), static_cast<int>(text.size()), MPI_CHAR, rank, tag, MPI_COMM_WORLD);
}

std::string recv_text(const MPI_Status& status) {
  int n = 0;
  MPI_Get_count(&status, MPI_CHAR, &n);
  std::string text(static_cast<size_t>(std::max(0, n)), '\0');
  MPI_Recv(text.data(), n, MPI_CHAR, status.MPI_SOURCE, status.MPI_TAG, MPI_COMM_WORLD,
           MPI_STATUS_IGNORE);
  return text;
}

}  // namespace rt
