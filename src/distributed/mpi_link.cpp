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

bool band_needs_primary(const CliOptions& opt) {
  return opt.moments || opt.checkpoint_s > 0 || opt.resume || opt.skip_existing;
}

void send_band(int32_t index, const TileResult& r, bool final_band, int signal,
               const CliOptions& opt) {
  const std::string key = key_text(r.key);
  ResultHeader h;
  h.task = index;
  h.final_band = final_band ? 1 : 0;
  h.stopped = r.stopped ? 1 : 0;
  h.signal = signal;
  h.busy_s = r.busy_s;
  h.back_faces = r.back_faces;
  h.key_bytes = key.size();
  MPI_Send(&h, sizeof h, MPI_BYTE, 0, kTagResult, MPI_COMM_WORLD);
  static_assert(sizeof(int) == sizeof(int32_t), "row counts cross as int32");
  send_bytes(r.row_spp.data(), r.row_spp.size() * sizeof(int), 0, kTagFilm);
  if (!key.empty()) send_bytes(key.data(), key.size(), 0, kTagFilm);
  send_bytes(r.accum.data(), r.accum.size() * sizeof(PixelAccum), 0, kTagFilm);
  // First-hit facts go only into moment files and checkpoints; without them the band is 48
  // of 80 bytes a pixel.
  if (band_needs_primary(opt))
    send_bytes(r.primary.data(), r.primary.size() * sizeof(PrimaryInfo), 0, kTagFilm);
}

std::string key_text(const CheckpointKey& key) {
  std::string text;
  for (const auto& [name, value] : key) text += name + " " + value + "\n";
  return text;
}

CheckpointKey parse_key_text(const std::string& text) {
  CheckpointKey key;
  for (size_t at = 0; at < text.size();) {
    size_t nl = text.find('\n', at);
    if (nl == std::string::npos) nl = text.size();
    const std::string line = text.substr(at, nl - at);
    const size_t space = line.find(' ');
    key.emplace_back(line.substr(0, space),
                     space == std::string::npos ? "" : line.substr(space + 1));
    at = nl + 1;
  }
  return key;
}

}  // namespace rt
