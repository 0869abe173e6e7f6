#include "integrator/render_scheduler.h"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace rt {

RenderScheduler::RenderScheduler(int width, int height, int samples, int row_alignment,
                                 int row_begin, int row_end)
    : width_(width),
      height_(height),
      samples_(samples),
      align_(std::max(1, row_alignment)),
      row_begin_(row_begin),
      row_end_(row_end < 0 ? height : row_end),
      row_cost_(static_cast<size_t>(std::max(0, height)), 0.0) {}

std::vector<RenderWork> RenderScheduler::plan() const {
  std::vector<RenderWork> pass;
  if (done_ >= samples_ || width_ <= 0 || row_end_ <= row_begin_) return pass;
  double image_cost = 0;  // One sample of the whole image, estimated.
  for (int y = row_begin_; y < row_end_; ++y) image_cost += row_cost_[y];
  int n = 1;
  if (measured_) {
    // As many samples as fit in kTargetSeconds over a band of kMinBandPixels (the whole
    // tile when it is smaller): each launch then runs several samples of a pixel in a row,
    // and a pixel's setup (its film, its sample keys) is paid once for all of them.
    const int tile_rows = row_end_ - row_begin_;
    const int min_rows = std::min(
        tile_rows, std::max(align_, static_cast<int>((kMinBandPixels + width_ - 1) / width_)));
    const double min_band_cost = image_cost * min_rows / tile_rows;
    long want = std::lround(kTargetSeconds / std::max(min_band_cost, 1e-9));
    n = static_cast<int>(
        std::clamp<long>(want, 1, std::min<long>(4L * last_pass_samples_, 1L << 20)));
    const double per_sample = std::max(image_cost, 1e-12);
    if (cap_seconds_ > 0)
      n = static_cast<int>(std::clamp<double>(std::floor(cap_seconds_ / per_sample), 1, n));
    // A last pass no larger than this one is taken with it (see the header).
    const int rest = samples_ - done_;
    if (take_rest_ && rest <= 2 * n && (cap_seconds_ <= 0 || rest * per_sample <= cap_seconds_))
      n = rest;
  }
  const bool banded = measured_ && image_cost * n > kSplitSeconds;
  const int s1 = std::min(samples_, done_ + n);
  for (int row = row_begin_; row < row_end_;) {
    int rows = row_end_ - row;
    if (banded) {
      // Rows until the estimate reaches the target, rounded to the device's alignment.
      double acc = 0;
      int k = 0;
      while (row + k < row_end_ && acc < kTargetSeconds) acc += row_cost_[row + k++] * (s1 - done_);
      k = (k + align_ / 2) / align_ * align_;
      rows = std::min(std::max(k, align_), row_end_ - row);
    }
    pass.push_back({row, row + rows, done_, s1});
    row += rows;
  }
  return pass;
}

double RenderScheduler::estimate_seconds(const std::vector<RenderWork>& pass) const {
  double t = 0;
  for (const RenderWork& w : pass)
    for (int y = w.row_begin; y < w.row_end; ++y) t += row_cost_[y] * w.samples();
  return t;
}

void RenderScheduler::record(const RenderWork& work, double seconds) {
  const double per_row = seconds / (static_cast<double>(work.rows()) * work.samples());
  std::fill(row_cost_.begin() + work.row_begin, row_cost_.begin() + work.row_end, per_row);
  measured_ = true;
  if (work.row_end == row_end_) {
    done_ = work.sample_end;
    last_pass_samples_ = work.samples();
  }
}

int sample_rows(RenderDevice& device, const Camera& cam, int row_begin, int row_end,
                Progress& progress, const StopRule& stop, const std::atomic<bool>* cancel,
                bool* cancelled, const PassHooks* hooks) {
  using Clock = std::chrono::steady_clock;
  RenderScheduler scheduler(cam.width, cam.height, cam.samples, device.row_alignment(), row_begin,
                            row_end);
  if (stop.time_limit_s > 0 || stop.noise_target > 0) scheduler.keep_checkpoints();
  if (hooks) scheduler.start_at(std::min(hooks->start_sample, cam.samples));
  if (hooks && hooks->pass_seconds > 0) scheduler.cap_pass_seconds(hooks->pass_seconds);
  const auto start = Clock::now();
  auto since = [](Clock::time_point t) {
    return std::chrono::duration<double>(Clock::now() - t).count();
  };
  std::vector<PixelAccum> accum;
  // A device that counts rays only in the film (RenderDevice::render returns 0, as the
  // OpenCL one) gets its rate from the film read once after the first pass, which is one
  // sample of every pixel of the tile: its rays per pixel sample (the mean over the whole
  // tile) then stand for the later samples, whose expected count is the same. --stats and
  // the result count the film's rays exactly.
  double rays_per_sample = -1;  // < 0: not measured yet (or the device counts them itself).
  bool device_counts = false;
  for (std::vector<RenderWork> pass = scheduler.plan(); !pass.empty(); pass = scheduler.plan()) {
    // The pass that measures the rate reports its samples with its rays, after the film
    // is read, so no line shows its samples at a zero rate.
    const bool measure = !device_counts && rays_per_sample < 0 && progress.enabled();
    uint64_t pass_samples = 0, pass_rays = 0;
    for (const RenderWork& w : pass) {
      const auto t0 = Clock::now();
      const uint64_t rays = device.render(w);
      scheduler.record(w, since(t0));
      const uint64_t samples = static_cast<uint64_t>(w.rows()) * cam.width * w.samples();
      pass_samples += samples;
      pass_rays += rays;
      if (measure) continue;
      progress.add(samples, device_counts || rays_per_sample < 0
                                ? rays
                                : static_cast<uint64_t>(samples * rays_per_sample));
    }
    if (measure) {
      device_counts = pass_rays > 0;
      if (!device_counts) {
        device.read_accum(&accum);
        for (const PixelAccum& a : accum) pass_rays += a.rays;
        rays_per_sample = static_cast<double>(pass_rays) / std::max<uint64_t>(pass_samples, 1);
      }
      progress.add(pass_samples, pass_rays);
    }
    if (cancel && cancel->load()) {
      if (cancelled) *cancelled = scheduler.samples_done() < cam.samples;
      break;
    }
    const std::vector<RenderWork> next = scheduler.plan();
    if (next.empty()) break;
    if (hooks && hooks->after_pass) hooks->after_pass(scheduler.samples_done());
    if (stop.time_limit_s > 0 &&
        since(start) + scheduler.estimate_seconds(next) > stop.time_limit_s)
      break;
    if (stop.noise_target > 0 && scheduler.samples_done() >= 2) {
      device.read_accum(&accum);
      const double floor = noise_floor(accum, stop.tonemap_key);
      if (relative_noise(accum, cam.width, floor) < stop.noise_target) break;
    }
  }
  return scheduler.samples_done();
}

RenderResult render_camera(RenderDevice& device, const FlatScene& flat, const KernelConfig& kernel,
                           Progress& progress, const StopRule& stop,
                           const std::atomic<bool>* cancel, DeviceLoadInfo* load_info,
                           const PassHooks* hooks) {
  const Camera& cam = flat.header.camera;
  DeviceLoadInfo info = device.load(flat, kernel);
  if (load_info) *load_info = info;
  if (hooks && hooks->accum) device.write_film(*hooks->accum, *hooks->primary);
  progress.begin();  // The line's elapsed time and rate are the sampling's, as --stats's.
  RenderResult r;
  r.width = cam.width;
  r.height = cam.height;
  const auto start = std::chrono::steady_clock::now();
  r.spp = sample_rows(device, cam, 0, cam.height, progress, stop, cancel, &r.cancelled, hooks);
  device.read_accum(&r.accum);
  device.read_primary(&r.primary);
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  r.samples = static_cast<uint64_t>(r.accum.size()) * r.spp;
  for (const PixelAccum& a : r.accum) r.rays += a.rays;
  return r;
}

}  // namespace rt
