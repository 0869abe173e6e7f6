// Rank 0's book of a distributed job: which task goes next, where each band's film lands in
// its image, when an image is whole (then it is written, atomically), the first failure,
// the job's progress line and its figures (busy time per rank, bytes gathered).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "app/cli.h"
#include "app/progress.h"
#include "distributed/job_plan.h"
#include "integrator/render.h"

namespace rt {

class JobCoordinator {
 public:
  JobCoordinator(const CliOptions& opt, JobPlan plan, int ranks);
  // The next task for `rank`, or false when none is left or the job has failed.
  bool next(int rank, int32_t* task);
  const TileTask& task(int32_t index) const { return plan_.tasks[index]; }
  uint64_t task_pixels(int32_t index) const;
  // Where the film of task `index` goes (the image's film is allocated on first use).
  PixelAccum* accum_rows(int32_t index);
  PrimaryInfo* primary_rows(int32_t index);
  // The task's film is in place: counts it, and writes its image when the image is whole.
  // `remote_bytes`: what crossed the network for it (0 for rank 0's own tasks), in
  // `recv_s` seconds of rank 0's time.
  void complete(int rank, int32_t index, int spp, double busy_s, uint64_t remote_bytes,
                double recv_s);
  // Records the first failure ("rank R: reason"); no task is handed out after it.
  void fail(int rank, const std::string& why);
  bool failed() const { return !failure_.empty(); }
  const std::string& failure() const { return failure_; }
  void set_device_name(const std::string& name) { device_name_ = name; }
  // The progress line's last state; with --stats one line of the job's figures.
  void finish(double wall_s);
  // Redraws the progress line now and then while tasks run (rank 0's loop calls it).
  void tick() { progress_.tick(); }

 private:
  struct ImageFilm {
    RenderResult r;
    int rows_left = 0;
    double busy_s = 0;  // The ranks' seconds on its tasks, for its "wrote" line.
  };
  ImageFilm& film(int32_t index);

  const CliOptions& opt_;
  JobPlan plan_;
  size_t next_ = 0;
  std::vector<ImageFilm> films_;
  std::vector<double> busy_s_;
  std::vector<int> tasks_done_;
  uint64_t gathered_bytes_ = 0;
  double recv_s_ = 0, write_s_ = 0;  // Rank 0's serial work: receiving bands, writing images.
  int images_written_ = 0;
  std::string failure_, device_name_;
  JobProgress progress_;
};

}  // namespace rt
