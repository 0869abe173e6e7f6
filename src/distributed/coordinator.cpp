#include "distributed/coordinator.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>

#include "app/backface_notice.h"
#include "app/interrupt.h"
#include "app/render_job.h"
#include "io/partial_mark.h"

namespace rt {
namespace {

using Clock = std::chrono::steady_clock;

int asked_spp(const CliOptions& opt, const PlannedImage& im) {
  return opt.render.spp > 0 ? opt.render.spp : im.desc.samples;
}

uint64_t job_samples(const CliOptions& opt, const JobPlan& plan) {
  uint64_t n = 0;
  for (const PlannedImage& im : plan.images)
    n += static_cast<uint64_t>(im.width) * im.height * asked_spp(opt, im);
  return n;
}

// The rows' counts of every checkpoint the job continues (read from their headers; a
// checkpoint that cannot be read is reported by the rank that loads it).
std::vector<std::vector<int>> resumed_rows(const CliOptions& opt, const JobPlan& plan) {
  std::vector<std::vector<int>> rows(plan.images.size());
  if (!opt.resume && !opt.skip_existing) return rows;
  for (size_t i = 0; i < plan.images.size(); ++i) {
    const std::string path = checkpoint_path_for(plan.images[i].path);
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) continue;
    try {
      const Checkpoint c = read_checkpoint_header(path);
      rows[i] = c.row_spp.empty() ? std::vector<int>(plan.images[i].height, c.spp) : c.row_spp;
      if (static_cast<int>(rows[i].size()) != plan.images[i].height) rows[i].clear();
    } catch (const std::exception&) {
    }
  }
  return rows;
}

uint64_t resumed_samples(const JobPlan& plan, const std::vector<std::vector<int>>& rows) {
  uint64_t n = 0;
  for (size_t i = 0; i < rows.size(); ++i)
    for (int spp : rows[i]) n += static_cast<uint64_t>(spp) * plan.images[i].width;
  return n;
}

double seconds_since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

}  // namespace

// Progress counts the pixel samples of finished tasks, from those the continued checkpoints
// hold. Rank 0's stderr is a pipe to mpirun: the line is drawn when mpirun's is a terminal.
JobCoordinator::JobCoordinator(const CliOptions& opt, JobPlan plan, int ranks)
    : opt_(opt),
      plan_(std::move(plan)),
      films_(plan_.images.size()),
      start_rows_(resumed_rows(opt, plan_)),
      busy_s_(ranks, 0.0),
      tasks_done_(ranks, 0),
      last_checkpoint_(Clock::now()),
      progress_(Progress::wanted_mpi(opt.quiet), static_cast<int>(plan_.images.size()),
                static_cast<int>(plan_.tasks.size()), job_samples(opt, plan_),
                resumed_samples(plan_, start_rows_)) {
  for (size_t i = 0; i < plan_.images.size(); ++i) films_[i].rows_left = plan_.images[i].height;
}

bool JobCoordinator::next(int rank, int32_t* task) {
  (void)rank;
  if (failed() || stop_requested().load() || next_ >= plan_.tasks.size()) return false;
  *task = static_cast<int32_t>(next_++);
  films_[plan_.tasks[*task].image].started = true;
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
    f.row_spp.assign(im.height, -1);
  }
  return f;
}

int JobCoordinator::asked(int image) const { return asked_spp(opt_, plan_.images[image]); }

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

void JobCoordinator::band(int rank, int32_t index, const BandInfo& info, uint64_t remote_bytes,
                          double recv_s) {
  const TileTask& t = plan_.tasks[index];
  ImageFilm& f = film(index);
  gathered_bytes_ += remote_bytes;
  recv_s_ += recv_s;
  std::copy(info.row_spp.begin(), info.row_spp.end(), f.row_spp.begin() + t.row_begin);
  f.key = info.key;
  f.dirty = true;
  if (!info.final_band) return;
  busy_s_[rank] += info.busy_s;
  ++tasks_done_[rank];
  f.rows_left -= t.row_end - t.row_begin;
  f.busy_s += info.busy_s;
  f.back_faces += info.back_faces;
  if (info.stopped) {
    f.stopped = true;
    request_stop(info.signal);  // One rank stopped: the job stops, as one process would.
  }
  uint64_t samples = 0;  // Taken by this task.
  const std::vector<int>& start = start_rows_[t.image];
  for (int y = t.row_begin; y < t.row_end; ++y)
    samples += static_cast<uint64_t>(
                   std::max(0, info.row_spp[y - t.row_begin] - (start.empty() ? 0 : start[y]))) *
               f.r.width;
  if (f.rows_left > 0 || f.stopped) {
    progress_.task_done(samples, false);
    return;
  }
  write_whole(t.image);
  progress_.task_done(samples, true);
}

void JobCoordinator::write_whole(int image) {
  ImageFilm& f = films_[image];
  const PlannedImage& im = plan_.images[image];
  // Under a stop rule images are whole tasks, so one rank's count holds for every pixel.
  f.r.spp = *std::min_element(f.row_spp.begin(), f.row_spp.end());
  f.r.samples = static_cast<uint64_t>(f.r.accum.size()) * f.r.spp;
  for (const PixelAccum& a : f.r.accum) f.r.rays += a.rays;
  const auto t0 = Clock::now();
  write_outputs(opt_, opt_.scenes[im.scene], im.camera, im.desc, device_name_, f.r, im.path);
  std::error_code ec;  // A checkpoint the image was continued from is done with.
  std::filesystem::remove(checkpoint_path_for(im.path), ec);
  write_s_ += seconds_since(t0);
  ++images_written_;
  f.written = true;
  progress_.clear();
  print_wrote(Progress::wanted_mpi(opt_.quiet), im.path, f.r.spp, f.busy_s);
  if (!opt_.quiet && !opt_.render.cull_back_faces && !back_face_notice_given_) {
    const std::string text =
        back_face_notice(static_cast<double>(f.back_faces) / static_cast<double>(f.r.accum.size()));
    back_face_notice_given_ = !text.empty();
    if (!text.empty()) std::fprintf(stderr, "notice: %s: %s\n", im.path.c_str(), text.c_str());
  }
  f.r = RenderResult();  // The image is on disk; its film is no longer needed.
}

int JobCoordinator::write_partial(int image, std::string* checkpoint) {
  ImageFilm& f = films_[image];
  if (f.written || f.key.empty()) return -1;
  const PlannedImage& im = plan_.images[image];
  const std::string path = checkpoint_path_for(im.path);
  std::error_code ec;
  // A checkpoint this job continues: rows no band has reached yet keep its film (the ranks
  // that loaded it checked its key).
  const bool continued = (opt_.resume || opt_.skip_existing) && std::filesystem::exists(path, ec);
  std::vector<int> rows = f.row_spp;
  if (continued && *std::min_element(rows.begin(), rows.end()) < 0) {
    const Checkpoint old = read_checkpoint(path);
    const size_t w = static_cast<size_t>(im.width);
    if (old.accum.size() != w * im.height)
      throw std::runtime_error(path + ": its film is not the image's");
    for (int y = 0; y < im.height; ++y) {
      if (rows[y] >= 0) continue;
      rows[y] = old.row_spp.empty() ? old.spp : old.row_spp[y];
      std::copy_n(old.accum.begin() + y * w, w, f.r.accum.begin() + y * w);
      std::copy_n(old.primary.begin() + y * w, w, f.r.primary.begin() + y * w);
    }
  }
  for (int& r : rows) r = std::max(r, 0);  // Rows not reached, with no film: none taken.
  f.r.spp = *std::min_element(rows.begin(), rows.end());
  const auto t0 = Clock::now();
  // The checkpoint first: an image marked partial has the film that continues it whenever
  // checkpoints are kept, as in one process (app/image_checkpoint.cpp).
  if (opt_.checkpoint_s > 0 || opt_.resume || continued) {
    Checkpoint c;
    c.key = f.key;
    c.spp = f.r.spp;
    if (*std::max_element(rows.begin(), rows.end()) != f.r.spp) c.row_spp = rows;
    c.accum = f.r.accum;
    c.primary = f.r.primary;
    write_checkpoint(path, c);
    *checkpoint = path;
  }
  write_outputs(opt_, opt_.scenes[im.scene], im.camera, im.desc, device_name_, f.r, im.path,
                samples_mark_text(f.r.spp, asked(image)));
  write_s_ += seconds_since(t0);
  return f.r.spp;
}

void JobCoordinator::checkpoint_due() {
  if (opt_.checkpoint_s <= 0 || seconds_since(last_checkpoint_) < opt_.checkpoint_s) return;
  for (size_t i = 0; i < films_.size(); ++i) {
    if (!films_[i].dirty || films_[i].written) continue;
    std::string path;
    const int spp = write_partial(static_cast<int>(i), &path);
    films_[i].dirty = false;
    if (opt_.stats && spp >= 0) {
      progress_.clear();
      std::fprintf(stderr, "stats: checkpoint: %s at %d of %d samples per pixel\n", path.c_str(),
                   spp, asked(static_cast<int>(i)));
    }
  }
  last_checkpoint_ = Clock::now();
}

void JobCoordinator::write_stopped() {
  progress_.clear();
  int left = 0;
  for (size_t i = 0; i < films_.size(); ++i) {
    if (films_[i].written) continue;
    std::string path;
    const int spp = films_[i].started ? write_partial(static_cast<int>(i), &path) : -1;
    if (spp < 0) {
      ++left;
      continue;
    }
    std::fprintf(stderr, "raytracer: interrupted: %s written with %d of %d samples per pixel%s%s\n",
                 plan_.images[i].path.c_str(), spp, asked(static_cast<int>(i)),
                 path.empty() ? "" : " and its checkpoint ", path.c_str());
  }
  if (left > 0)
    std::fprintf(stderr, "raytracer: interrupted: %d of %zu images were not rendered\n", left,
                 films_.size());
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
