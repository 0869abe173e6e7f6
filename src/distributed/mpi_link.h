// The messages of the distributed driver over MPI: small fixed records and the film of a
// band, sent as bytes (every rank runs the same executable on the same architecture).
// Waiting polls with short sleeps instead of MPI's busy-wait, so an idle rank leaves the
// cores it shares with its neighbours to them.
#pragma once

#include <mpi.h>

#include <cstdint>
#include <string>

#include "distributed/tile_worker.h"

namespace rt {

enum MpiTag : int { kTagReady = 1, kTagTask, kTagResult, kTagFilm, kTagError };

// The fixed part of a result; the film follows as kTagFilm messages.
struct ResultHeader {
  int32_t task = 0, spp = 0;
  double busy_s = 0;
};

// A task index into the plan's list, or kStopTask.
constexpr int32_t kStopTask = -1;

// Blocks until a message with `tag` from `source` (MPI_ANY_SOURCE) can be received, sleeping
// between polls; returns its status.
MPI_Status wait_for(int source, int tag);

// Sends / receives `bytes` bytes to / from `rank` as one or more messages of at most 1 GiB
// (MPI counts are ints).
void send_bytes(const void* data, uint64_t bytes, int rank, int tag);
void recv_bytes(void* data, uint64_t bytes, int rank, int tag);

void send_text(const std::string& text, int rank, int tag);
std::string recv_text(const MPI_Status& status);

}  // namespace rt
