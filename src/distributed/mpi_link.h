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

// kTagStop: rank 0 to a rank rendering, when the job stops (an interrupt): its task ends
// at the next pass.
enum MpiTag : int { kTagReady = 1, kTagTask, kTagResult, kTagFilm, kTagError, kTagStop };

// The fixed part of a band (a task's result, or its snapshot between passes under
// --checkpoint); unless `declined`, kTagFilm messages follow: the rows' sample counts
// (int32 each), the checkpoint key's text (key_bytes), the PixelAccum film, and the
// PrimaryInfo film when rank 0 asks for it (band_needs_primary).
struct ResultHeader {
  int32_t task = 0;
  int32_t final_band = 1;  // 0: a snapshot; the task goes on.
  int32_t stopped = 0;     // The job's stop ended the task early (TileResult::stopped).
  int32_t declined = 0;    // The task arrived after the stop: not started, no film.
  int32_t signal = 0;      // The signal that stopped the sending rank; 0: none.
  double busy_s = 0;
  uint64_t back_faces = 0, key_bytes = 0;
};

// True when bands carry their PrimaryInfo: moment files, and checkpoints (their film).
bool band_needs_primary(const CliOptions& opt);

// Rank > 0: sends task `index`'s band `r` to rank 0.
void send_band(int32_t index, const TileResult& r, bool final_band, int signal,
               const CliOptions& opt);

// The checkpoint key as "name value" lines, and back.
std::string key_text(const CheckpointKey& key);
CheckpointKey parse_key_text(const std::string& text);

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
