#include "distributed/mpi_render.h"

#include <mpi.h>

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <mutex>
#include <thread>

#include "app/progress.h"
#include "app/render_job.h"
#include "distributed/coordinator.h"
#include "distributed/mpi_link.h"
#include "distributed/tile_worker.h"
#include "util/parallel_for.h"

namespace rt {
namespace {

struct TaskMessage {
  int32_t index = kStopTask;
  TileTask task;
};

// Where this rank stands on its node: its device and its share of the cores follow.
struct NodePlace {
  int rank = 0, ranks = 1, local_rank = 0, local_ranks = 1, threads = 1;
};

NodePlace node_place(const CliOptions& opt) {
  NodePlace p;
  MPI_Comm_rank(MPI_COMM_WORLD, &p.rank);
  MPI_Comm_size(MPI_COMM_WORLD, &p.ranks);
  MPI_Comm node;
  MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, p.rank, MPI_INFO_NULL, &node);
  MPI_Comm_rank(node, &p.local_rank);
  MPI_Comm_size(node, &p.local_ranks);
  MPI_Comm_free(&node);
  // --threads as given, else the node's cores shared among the node's ranks.
  p.threads = opt.threads > 0 ? opt.threads : std::max(1, resolve_threads(0) / p.local_ranks);
  // PoCL's CPU device would start a thread per core in every rank; it reads this at start.
  if (p.local_ranks > 1 && !std::getenv("POCL_MAX_PTHREAD_COUNT"))
    setenv("POCL_MAX_PTHREAD_COUNT", std::to_string(p.threads).c_str(), 1);
  return p;
}

#ifdef RT_MPI_FAULT_INJECTION
// Fault injection, compiled only into the test executable raytracer_mpi_faults
// (tests/CMakeLists.txt), never into raytracer: RT_MPI_FAULT=<rank>:kill makes that rank
// (not 0) die by SIGKILL when its second task arrives; <rank>:fail makes its second task
// throw.
bool fault_due(int rank, int tasks_received, const char* kind) {
  const char* f = std::getenv("RT_MPI_FAULT");
  if (!f || tasks_received != 2) return false;
  const std::string spec = f;
  return spec == std::to_string(rank) + ":" + kind;
}
#else
constexpr bool fault_due(int, int, const char*) { return false; }
#endif

// Ranks above 0: ask, render, send the band back, until told to stop or a task fails.
void serve(const CliOptions& opt, const NodePlace& place) {
  std::unique_ptr<TileWorker> worker;
  try {
    worker = std::make_unique<TileWorker>(opt, place.local_rank, place.threads);
  } catch (const std::exception& e) {
    send_text(e.what(), 0, kTagError);
    return;
  }
  MPI_Send(nullptr, 0, MPI_BYTE, 0, kTagReady, MPI_COMM_WORLD);
  for (int received = 1;; ++received) {
    TaskMessage m;
    wait_for(0, kTagTask);
    MPI_Recv(&m, sizeof m, MPI_BYTE, 0, kTagTask, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    if (m.index == kStopTask) return;
    if (fault_due(place.rank, received, "kill")) std::raise(SIGKILL);
    TileResult r;
    try {
      if (fault_due(place.rank, received, "fail")) throw std::runtime_error("injected failure");
      r = worker->render(m.task);
    } catch (const std::exception& e) {
      send_text(e.what(), 0, kTagError);
      return;
    }
    const ResultHeader h{m.index, r.spp, r.busy_s};
    MPI_Send(&h, sizeof h, MPI_BYTE, 0, kTagResult, MPI_COMM_WORLD);
    send_bytes(r.accum.data(), r.accum.size() * sizeof(PixelAccum), 0, kTagFilm);
    // First-hit facts only go into moment files; without them the band is 48 of 80 bytes.
    if (opt.moments)
      send_bytes(r.primary.data(), r.primary.size() * sizeof(PrimaryInfo), 0, kTagFilm);
  }
}

// Rank 0's own worker: a thread rendering the tasks the coordinating thread hands it, so
// only that thread calls MPI.
class LocalWorker {
 public:
  LocalWorker(const CliOptions& opt, const NodePlace& place)
      : thread_([this, &opt, place] { loop(opt, place); }) {}
  ~LocalWorker() {
    {
      std::lock_guard<std::mutex> lock(m_);
      quit_ = true;
    }
    cv_.notify_all();
    thread_.join();
  }
  void assign(int32_t index, const TileTask& task) {
    {
      std::lock_guard<std::mutex> lock(m_);
      index_ = index;
      task_ = task;
    }
    cv_.notify_all();
  }
  // Takes a finished result (true), or the failure (*error set); false while busy.
  bool poll(int32_t* index, TileResult* result, std::string* error) {
    std::lock_guard<std::mutex> lock(m_);
    if (!error_.empty()) {
      *error = error_;
      error_.clear();
      return false;
    }
    if (!done_) return false;
    done_ = false;
    *index = done_index_;
    *result = std::move(result_);
    return true;
  }
  std::string device_name() {
    std::unique_lock<std::mutex> lock(m_);
    cv_.wait(lock, [this] { return opened_; });
    return device_name_;
  }

 private:
  void loop(const CliOptions& opt, const NodePlace& place) {
    std::unique_ptr<TileWorker> worker;
    try {
      worker = std::make_unique<TileWorker>(opt, place.local_rank, place.threads);
    } catch (const std::exception& e) {
      std::lock_guard<std::mutex> lock(m_);
      error_ = e.what();
    }
    {
      std::lock_guard<std::mutex> lock(m_);
      opened_ = true;
      if (worker) device_name_ = worker->device_name();
    }
    cv_.notify_all();
    if (!worker) return;
    for (;;) {
      std::unique_lock<std::mutex> lock(m_);
      cv_.wait(lock, [this] { return quit_ || index_ != kStopTask; });
      if (quit_) return;
      const int32_t index = index_;
      const TileTask task = task_;
      index_ = kStopTask;
      lock.unlock();
      try {
        TileResult r = worker->render(task);
        lock.lock();
        result_ = std::move(r);
        done_index_ = index;
        done_ = true;
      } catch (const std::exception& e) {
        lock.lock();
        error_ = e.what();
        return;
      }
    }
  }

  std::mutex m_;
  std::condition_variable cv_;
  bool quit_ = false, done_ = false, opened_ = false;
  int32_t index_ = kStopTask, done_index_ = kStopTask;
  TileTask task_;
  TileResult result_;
  std::string error_, device_name_;
  std::thread thread_;
};

// Rank 0: hands out tasks, gathers bands, writes images, until every rank has stopped.
int coordinate(const CliOptions& opt, const NodePlace& place) {
  const auto start = std::chrono::steady_clock::now();
  // Rank 0 gathers each tile only when it is done, so it has no film to save between
  // passes; --resume and --skip-existing do continue checkpoints here (tile_worker.cpp).
  if (opt.checkpoint_s > 0 && !opt.quiet)
    std::fprintf(stderr,
                 "notice: --checkpoint writes nothing under mpirun (a checkpoint made in one "
                 "process is continued here with --resume)\n");
  std::string setup_error;
  JobPlan plan;
  try {
    check_output_dir(opt);
    // Listing the images loads every scene file: the terminal says so meanwhile.
    show_status(Progress::wanted_mpi(opt.quiet), "loading the scene files to plan the job...");
    plan = plan_job(opt, place.ranks);
  } catch (const std::exception& e) {
    setup_error = e.what();
  }
  clear_status(Progress::wanted_mpi(opt.quiet));
  JobCoordinator job(opt, std::move(plan), place.ranks);
  int running = place.ranks;  // Ranks not yet stopped, this one's worker included.
  std::unique_ptr<LocalWorker> local;
  if (setup_error.empty()) {
    local = std::make_unique<LocalWorker>(opt, place);
    job.set_device_name(local->device_name());
  } else {
    --running;
  }
  // Gives `rank` its next task, or stops it.
  auto hand_out = [&](int rank) {
    TaskMessage m;
    if (!job.next(rank, &m.index)) m.index = kStopTask;
    if (m.index != kStopTask) m.task = job.task(m.index);
    if (rank == 0) {
      if (m.index == kStopTask)
        --running, local.reset();
      else
        local->assign(m.index, m.task);
    } else {
      MPI_Send(&m, sizeof m, MPI_BYTE, rank, kTagTask, MPI_COMM_WORLD);
      if (m.index == kStopTask) --running;
    }
  };
  if (local) hand_out(0);
  while (running > 0) {
    bool idle = true;
    int flag = 0;
    MPI_Status st;
    MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &flag, &st);
    if (flag) {
      idle = false;
      const int src = st.MPI_SOURCE;
      if (st.MPI_TAG == kTagReady) {
        MPI_Recv(nullptr, 0, MPI_BYTE, src, kTagReady, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        hand_out(src);
      } else if (st.MPI_TAG == kTagError) {
        job.fail(src, recv_text(st));
        --running;  // A failed rank leaves on its own.
      } else if (st.MPI_TAG == kTagResult) {
        ResultHeader h;
        MPI_Recv(&h, sizeof h, MPI_BYTE, src, kTagResult, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        const uint64_t pixels = job.task_pixels(h.task);
        const auto t0 = std::chrono::steady_clock::now();
        recv_bytes(job.accum_rows(h.task), pixels * sizeof(PixelAccum), src, kTagFilm);
        if (opt.moments)
          recv_bytes(job.primary_rows(h.task), pixels * sizeof(PrimaryInfo), src, kTagFilm);
        try {
          job.complete(
              src, h.task, h.spp, h.busy_s,
              pixels * (sizeof(PixelAccum) + (opt.moments ? sizeof(PrimaryInfo) : 0)),
              std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
        } catch (const std::exception& e) {
          job.fail(0, e.what());  // Writing the image failed on this rank.
        }
        hand_out(src);
      }
    }
    if (local) {
      int32_t index;
      TileResult r;
      std::string error;
      if (local->poll(&index, &r, &error)) {
        idle = false;
        std::copy(r.accum.begin(), r.accum.end(), job.accum_rows(index));
        std::copy(r.primary.begin(), r.primary.end(), job.primary_rows(index));
        try {
          job.complete(0, index, r.spp, r.busy_s, 0, 0);
        } catch (const std::exception& e) {
          job.fail(0, e.what());
        }
        hand_out(0);
      } else if (!error.empty()) {
        idle = false;
        job.fail(0, error);
        --running;
        local.reset();
      }
    }
    if (idle) {
      job.tick();
      std::this_thread::sleep_for(std::chrono::microseconds(500));
    }
  }
  job.finish(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  if (!setup_error.empty()) {
    std::fprintf(stderr, "raytracer: error: %s\n", setup_error.c_str());
    return 1;
  }
  if (job.failed()) {
    std::fprintf(stderr, "raytracer: error: %s; the images it was rendering were not written\n",
                 job.failure().c_str());
    return 1;
  }
  return 0;
}

}  // namespace

bool launched_by_mpi() {
  return std::getenv("OMPI_COMM_WORLD_SIZE") || std::getenv("PMI_SIZE") || std::getenv("PMIX_RANK");
}

int render_distributed(const CliOptions& opt) {
  int provided = 0;
  MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
  int status = 0;
  try {
    const NodePlace place = node_place(opt);
    if (place.rank == 0)
      status = coordinate(opt, place);
    else
      serve(opt, place);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "raytracer: error: %s\n", e.what());
    MPI_Abort(MPI_COMM_WORLD, 1);
  }
  MPI_Finalize();
  return status;
}

}  // namespace rt
