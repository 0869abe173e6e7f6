// Rank 0's own worker (distributed/mpi_render.cpp): a thread rendering the tasks the
// coordinating thread hands it, so only that thread calls MPI. Its bands (results, and
// snapshots under --checkpoint) wait here until that thread takes them.
#pragma once

#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <string>
#include <thread>

#include "app/cli.h"
#include "distributed/tile_worker.h"

namespace rt {

class LocalWorker {
 public:
  // Opens the device of GPU `gpu_rank` (or the CPU reference with `threads` threads) on its
  // thread.
  LocalWorker(const CliOptions& opt, int gpu_rank, int threads);
  ~LocalWorker();
  // Starts task `index` (the worker is idle).
  void assign(int32_t index, const TileTask& task);
  // Takes a finished result (true; its row_spp empty when the task came after the job's
  // stop and was not started), or the failure (*error set); false while busy.
  bool poll(int32_t* index, TileResult* result, std::string* error);
  // Takes the latest snapshot of the running task, if one is waiting.
  bool poll_snapshot(int32_t* index, TileResult* snapshot);
  // Waits until the device is open; "" when it failed (poll gives the reason).
  std::string device_name();

 private:
  void loop(const CliOptions& opt, int gpu_rank, int threads);

  std::mutex m_;
  std::condition_variable cv_;
  bool quit_ = false, done_ = false, opened_ = false, has_snapshot_ = false;
  int32_t index_ = -1, done_index_ = -1, running_ = -1;  // -1: none.
  TileTask task_;
  TileResult result_, snapshot_;
  std::string error_, device_name_;
  std::thread thread_;
};

}  // namespace rt
