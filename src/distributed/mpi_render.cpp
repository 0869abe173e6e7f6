#include "distributed/mpi_render.h"

#include <mpi.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <thread>

#include "app/interrupt.h"
#include "app/progress.h"
#include "app/render_job.h"
#include "distributed/coordinator.h"
#include "distributed/local_worker.h"
#include "distributed/mpi_link.h"
#include "distributed/tile_worker.h"
#include "util/parallel_for.h"

namespace rt {
namespace {

struct TaskMessage {
  int32_t index = kStopTask;
  int32_t stop_sent = 0;  // With kStopTask: rank 0 sent this rank kTagStop before it.
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

BandInfo band_info(const TileResult& r, bool final_band, int signal) {
  BandInfo b;
  b.row_spp = r.row_spp;
  b.key = r.key;
  b.final_band = final_band;
  b.stopped = r.stopped;
  b.signal = signal;
  b.busy_s = r.busy_s;
  b.back_faces = r.back_faces;
  return b;
}

// Ranks above 0: ask, render, send the band back, until told to stop or a task fails. The
// job's stop (a signal here, or rank 0's kTagStop) ends the task at a pass; its band goes
// back with the samples taken.
void serve(const CliOptions& opt, const NodePlace& place) {
  std::unique_ptr<TileWorker> worker;
  try {
    worker = std::make_unique<TileWorker>(opt, place.local_rank, place.threads);
  } catch (const std::exception& e) {
    send_text(e.what(), 0, kTagError);
    return;
  }
  bool told_to_stop = false;
  auto receive_stop = [&] {
    MPI_Recv(nullptr, 0, MPI_BYTE, 0, kTagStop, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    told_to_stop = true;
    request_stop(0);
  };
  auto poll_stop = [&] {
    int flag = 0;
    MPI_Iprobe(0, kTagStop, MPI_COMM_WORLD, &flag, MPI_STATUS_IGNORE);
    if (flag) receive_stop();
  };
  MPI_Send(nullptr, 0, MPI_BYTE, 0, kTagReady, MPI_COMM_WORLD);
  for (int received = 1;; ++received) {
    TaskMessage m;
    wait_for(0, kTagTask);
    MPI_Recv(&m, sizeof m, MPI_BYTE, 0, kTagTask, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    if (m.index == kStopTask) {
      if (m.stop_sent && !told_to_stop) {  // No message is left unreceived at MPI_Finalize.
        wait_for(0, kTagStop);
        receive_stop();
      }
      return;
    }
    if (fault_due(place.rank, received, "kill")) std::raise(SIGKILL);
    if (stop_requested().load()) {
      ResultHeader h;
      h.task = m.index;
      h.declined = 1;
      h.signal = stop_signal();
      MPI_Send(&h, sizeof h, MPI_BYTE, 0, kTagResult, MPI_COMM_WORLD);
      continue;
    }
    TileResult r;
    try {
      if (fault_due(place.rank, received, "fail")) throw std::runtime_error("injected failure");
      r = worker->render(
          m.task,
          [&](const TileResult& snap) { send_band(m.index, snap, false, stop_signal(), opt); },
          poll_stop);
    } catch (const std::exception& e) {
      send_text(e.what(), 0, kTagError);
      return;
    }
    send_band(m.index, r, true, stop_signal(), opt);
  }
}

// Receives the film of a band whose header `h` came from `src` into the job's image.
BandInfo receive_band(JobCoordinator& job, const CliOptions& opt, const ResultHeader& h, int src,
                      uint64_t* bytes) {
  const TileTask& t = job.task(h.task);
  const uint64_t pixels = job.task_pixels(h.task);
  BandInfo b;
  b.final_band = h.final_band != 0;
  b.stopped = h.stopped != 0;
  b.signal = h.signal;
  b.busy_s = h.busy_s;
  b.back_faces = h.back_faces;
  b.row_spp.resize(t.row_end - t.row_begin);
  recv_bytes(b.row_spp.data(), b.row_spp.size() * sizeof(int), src, kTagFilm);
  if (h.key_bytes > 0) {
    std::string key(h.key_bytes, '\0');
    recv_bytes(key.data(), key.size(), src, kTagFilm);
    b.key = parse_key_text(key);
  }
  recv_bytes(job.accum_rows(h.task), pixels * sizeof(PixelAccum), src, kTagFilm);
  *bytes = b.row_spp.size() * sizeof(int) + h.key_bytes + pixels * sizeof(PixelAccum);
  if (band_needs_primary(opt)) {
    recv_bytes(job.primary_rows(h.task), pixels * sizeof(PrimaryInfo), src, kTagFilm);
    *bytes += pixels * sizeof(PrimaryInfo);
  }
  return b;
}

// Rank 0: hands out tasks, gathers bands, writes images, until every rank has stopped.
int coordinate(const CliOptions& opt, const NodePlace& place) {
  const auto start = std::chrono::steady_clock::now();
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
  std::vector<char> active(place.ranks, 1), stop_sent(place.ranks, 0);
  std::unique_ptr<LocalWorker> local;
  if (setup_error.empty()) {
    local = std::make_unique<LocalWorker>(opt, place.local_rank, place.threads);
    job.set_device_name(local->device_name());
  } else {
    --running;
  }
  // Gives `rank` its next task, or stops it.
  auto hand_out = [&](int rank) {
    TaskMessage m;
    if (!job.next(rank, &m.index)) m.index = kStopTask;
    if (m.index != kStopTask) m.task = job.task(m.index);
    m.stop_sent = stop_sent[rank];
    if (rank == 0) {
      if (m.index == kStopTask)
        --running, local.reset();
      else
        local->assign(m.index, m.task);
    } else {
      MPI_Send(&m, sizeof m, MPI_BYTE, rank, kTagTask, MPI_COMM_WORLD);
      if (m.index == kStopTask) --running, active[rank] = 0;
    }
  };
  // A band's film is in place: records it (a failed write fails the job on this rank).
  auto take = [&](int rank, int32_t index, const BandInfo& b, uint64_t bytes, double recv_s) {
    try {
      job.band(rank, index, b, bytes, recv_s);
    } catch (const std::exception& e) {
      job.fail(0, e.what());
    }
  };
  if (local) hand_out(0);
  bool stopping = false;
  while (running > 0) {
    if (stop_requested().load() && !stopping) {
      stopping = true;  // The ranks still rendering end their tasks at their next pass.
      for (int r = 1; r < place.ranks; ++r)
        if (active[r]) {
          MPI_Send(nullptr, 0, MPI_BYTE, r, kTagStop, MPI_COMM_WORLD);
          stop_sent[r] = 1;
        }
    }
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
        active[src] = 0;
      } else if (st.MPI_TAG == kTagResult) {
        ResultHeader h;
        MPI_Recv(&h, sizeof h, MPI_BYTE, src, kTagResult, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        if (h.declined) {
          request_stop(h.signal);
          hand_out(src);
        } else {
          const auto t0 = std::chrono::steady_clock::now();
          uint64_t bytes = 0;
          const BandInfo b = receive_band(job, opt, h, src, &bytes);
          take(src, h.task, b, bytes,
               std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
          if (b.final_band) hand_out(src);
        }
      }
    }
    if (local) {
      int32_t index;
      TileResult r;
      std::string error;
      if (local->poll_snapshot(&index, &r)) {
        std::copy(r.accum.begin(), r.accum.end(), job.accum_rows(index));
        std::copy(r.primary.begin(), r.primary.end(), job.primary_rows(index));
        take(0, index, band_info(r, false, stop_signal()), 0, 0);
      }
      if (local->poll(&index, &r, &error)) {
        idle = false;
        if (!r.row_spp.empty()) {
          std::copy(r.accum.begin(), r.accum.end(), job.accum_rows(index));
          std::copy(r.primary.begin(), r.primary.end(), job.primary_rows(index));
          take(0, index, band_info(r, true, stop_signal()), 0, 0);
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
      if (!stopping) {
        try {
          job.checkpoint_due();
        } catch (const std::exception& e) {
          job.fail(0, e.what());
        }
      }
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
  if (stop_requested().load()) {
    try {
      job.write_stopped();
    } catch (const std::exception& e) {
      std::fprintf(stderr, "raytracer: error: %s\n", e.what());
      return 1;
    }
    return interrupt_exit_status();
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
    // mpirun turns a Ctrl-C into SIGTERM to every rank; rank 0 alone speaks.
    install_interrupt_handlers(opt.quiet || place.rank != 0, true);
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
