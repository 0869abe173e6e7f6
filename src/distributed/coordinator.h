// Rank 0's book of a distributed job: which task goes next, where each band's film lands in
// its image, when an image is whole (then it is written, atomically), the first failure,
// the job's stop (an interrupt: images in progress written partial, with their checkpoints
// when checkpoints are kept), the checkpoints of --checkpoint, the job's progress line and
// its figures (busy time per rank, bytes gathered).
#pragma once

#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

#include "app/cli.h"
#include "app/progress.h"
#include "distributed/job_plan.h"
#include "integrator/render.h"
#include "io/checkpoint.h"

namespace rt {

// What came with a band's film (TileResult, ResultHeader).
struct BandInfo {
  std::vector<int> row_spp;
  CheckpointKey key;
  bool final_band = true, stopped = false;
  int signal = 0;  // The signal that stopped the rank that sent it; 0: none.
  double busy_s = 0;
  uint64_t back_faces = 0;
};

class JobCoordinator {
 public:
  JobCoordinator(const CliOptions& opt, JobPlan plan, int ranks);
  // The next task for `rank`, or false when none is left, the job has failed or stops.
  bool next(int rank, int32_t* task);
  const TileTask& task(int32_t index) const { return plan_.tasks[index]; }
  uint64_t task_pixels(int32_t index) const;
  // Where the film of task `index` goes (the image's film is allocated on first use).
  PixelAccum* accum_rows(int32_t index);
  PrimaryInfo* primary_rows(int32_t index);
  // The band's film is in place: a snapshot is kept for the next checkpoint; a final band
  // counts its task, and writes its image when the image is whole. A stopped band stops the
  // job (stop_requested). `remote_bytes`: what crossed the network for it (0 for rank 0's
  // own tasks), in `recv_s` seconds of rank 0's time.
  void band(int rank, int32_t index, const BandInfo& info, uint64_t remote_bytes, double recv_s);
  // Records the first failure ("rank R: reason"); no task is handed out after it.
  void fail(int rank, const std::string& why);
  bool failed() const { return !failure_.empty(); }
  const std::string& failure() const { return failure_; }
  void set_device_name(const std::string& name) { device_name_ = name; }
  // With --checkpoint S, every S seconds: writes each image with bands since its last
  // checkpoint, partial, with its checkpoint.
  void checkpoint_due();
  // After an interrupt, once every rank has stopped: writes every image in progress with
  // the samples it has, marked partial, each with a line "interrupted: ... written with N
  // of M samples per pixel".
  void write_stopped();
  // The progress line's last state; with --stats one line of the job's figures.
  void finish(double wall_s);
  // Redraws the progress line now and then while tasks run (rank 0's loop calls it).
  void tick() { progress_.tick(); }

 private:
  struct ImageFilm {
    RenderResult r;
    std::vector<int> row_spp;  // Samples each row holds; -1: no band of it received.
    int rows_left = 0;         // Rows whose task's final band has not arrived.
    double busy_s = 0;         // The ranks' seconds on its tasks, for its "wrote" line.
    uint64_t back_faces = 0;
    CheckpointKey key;
    bool started = false, stopped = false, dirty = false, written = false;
  };
  ImageFilm& film(int32_t index);
  int asked(int image) const;
  void write_whole(int image);
  // Writes image `image` partial (and its checkpoint when checkpoints are kept); returns
  // the least sample count of its rows, -1 when it has no band to write.
  int write_partial(int image, std::string* checkpoint);

  const CliOptions& opt_;
  JobPlan plan_;
  size_t next_ = 0;
  std::vector<ImageFilm> films_;
  // Samples each row of an image holds before this job (a checkpoint it continues); empty
  // for an image started afresh. The progress counts from them.
  std::vector<std::vector<int>> start_rows_;
  std::vector<double> busy_s_;
  std::vector<int> tasks_done_;
  uint64_t gathered_bytes_ = 0;
  double recv_s_ = 0, write_s_ = 0;  // Rank 0's serial work: receiving bands, writing images.
  int images_written_ = 0;
  bool back_face_notice_given_ = false;
  std::chrono::steady_clock::time_point last_checkpoint_;
  std::string failure_, device_name_;
  JobProgress progress_;
};

}  // namespace rt
