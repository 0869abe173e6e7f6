#include "distributed/coordinator.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>

#include "app/render_job.h"
#include "io/checkpoint.h"

namespace rt {
namespace {

uint64_t job_pixels(const JobPlan& plan) {
  uint64_t n = 0;
  for (const PlannedImage& im : plan.images) n += static_cast<uint64_t>(im.width) * im.height;
  return n;
}

}  // namespace

// Progress counts pixels finished (the sample counts of images may differ). Rank 0's
// stderr is a pipe to mpirun: the line is drawn when mpirun's is a terminal.
JobCoordinator::JobCoordinator(const CliOptions& opt, JobPlan plan, int ranks)
    : opt_(opt),
      plan_(std::move(plan)),
      films_(plan_.images.size()),
      busy_s_(ranks, 0.0),
      tasks_done_(ranks, 0),
      progress_(Progress::wanted_mpi(opt.quiet), static_cast<int>(plan_.images.size()),
                static_cast<int>(plan_.tasks.size()), job_pixels(plan_)) {
  for (size_t i = 0; i < plan_.images.size(); ++i) films_[i].rows_left = plan_.images[i].height;
}

bool JobCoordinator::next(int rank, int32_t* task) {
  (void)rank;
  if (failed() || next_ >= plan_.tasks.size()) return false;
  *task = static_cast<int32_t>(next_++);
  return true;
}

JobCoordinator::ImageFilm& JobCoordinator::film(int32_t index) {
  const PlannedImage& im = plan_.images[plan_.tasks[index].image];
  ImageFilm& f = films_[plan_.tasks[index].image];
  if (f.r.accum.empty()) {
    const size_t pixels = static_cast<size_t>(im.width) * im.height;
    f.r.width = im.width;
    f.r.height = im.height;
    f.r.accum.assign(pixels, PixelAccum{});
    f.r.primary.assign(pixels, PrimaryInfo{});
  }
  return f;
}

uint64_t JobCoordinator::task_pixels(int32_t index) const {
  const TileTask& t = plan_.tasks[index];
  return static_cast<uint64_t>(t.row_end - t.row_begin) * plan_.images[t.image].width;
}

PixelAccum* JobCoordinator::accum_rows(int32_t index) {
  const TileTask& t = plan_.tasks[index];
  return film(index).r.accum.data() + static_cast<size_t>(t.row_begin) * film(index).r.width;
}

PrimaryInfo* JobCoordinator::primary_rows(int32_t index) {
  const TileTask& t = plan_.tasks[index];
  return film(index).r.primary.data() + static_cast<size_t>(t.row_begin) * film(index).r.width;
}

void JobCoordinator::complete(int rank, int32_t index, int spp, double busy_s,
                              uint64_t remote_bytes, double recv_s) {
  const TileTask& t = plan_.tasks[index];
  ImageFilm& f = film(index);
  busy_s_[rank] += busy_s;
  ++tasks_done_[rank];
  gathered_bytes_ += remote_bytes;
  recv_s_ += recv_s;
  // Under a stop rule images are whole tasks, so one rank's count holds for every pixel.
  f.r.spp = spp;
  f.rows_left -= t.row_end - t.row_begin;
  f.busy_s += busy_s;
  const uint64_t pixels = static_cast<uint64_t>(t.row_end - t.row_begin) * f.r.width;
  if (f.rows_left > 0) {
    progress_.task_done(pixels, false);
    return;
  }
  f.r.samples = static_cast<uint64_t>(f.r.accum.size()) * f.r.spp;
  for (const PixelAccum& a : f.r.accum) f.r.rays += a.rays;
  const PlannedImage& im = plan_.images[t.image];
  const auto t0 = std::chrono::steady_clock::now();
  write_outputs(opt_, opt_.scenes[im.scene], im.camera, im.desc, device_name_, f.r, im.path);
  std::error_code ec;  // A checkpoint the image was continued from is done with.
  std::filesystem::remove(checkpoint_path_for(im.path), ec);
  write_s_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  ++images_written_;
  progress_.clear();
  print_wrote(Progress::wanted_mpi(opt_.quiet), im.path, f.r.spp, f.busy_s);
  progress_.task_done(pixels, true);
  f.r = RenderResult();  // The image is on disk; its film is no longer needed.
}

void JobCoordinator::fail(int rank, const std::string& why) {
  if (failure_.empty()) failure_ = "rank " + std::to_string(rank) + ": " + why;
}

void JobCoordinator::finish(double wall_s) {
  progress_.finish();
  if (!opt_.stats) return;
  double total = 0, most = 0;
  for (double b : busy_s_) {
    total += b;
    most = std::max(most, b);
  }
  const double mean = total / static_cast<double>(busy_s_.size());
  std::fprintf(stderr,
               "stats: mpi: %zu ranks | %d of %zu images written | %zu tasks (tile rows %d) | "
               "wall %.3f s | busy mean %.3f s max %.3f s | imbalance %.1f %% | gathered %llu "
               "bytes in %.3f s | writing %.3f s | busy per rank:",
               busy_s_.size(), images_written_, plan_.images.size(), plan_.tasks.size(),
               plan_.tile_rows, wall_s, mean, most, most > 0 ? 100.0 * (1.0 - mean / most) : 0.0,
               static_cast<unsigned long long>(gathered_bytes_), recv_s_, write_s_);
  for (size_t r = 0; r < busy_s_.size(); ++r)
    std::fprintf(stderr, " %.3f (%d)", busy_s_[r], tasks_done_[r]);
  std::fprintf(stderr, "\n");
}

}  // namespace rt
