// The one scheduler of every render: it sizes the passes of samples from measured costs,
// applies the stop rules (--time-limit, --noise-target) and cancellation between passes,
// reports progress and gathers the run's figures, for any RenderDevice.
//
// Policy (one for every device): a pass covers the whole image once with the same samples,
// so every pixel always holds the same sample count. The first pass is one sample of the
// whole image; its time, then each band's, gives a cost per row and sample. Later passes
// take as many samples as fit in about kTargetSeconds over a band of kMinBandPixels (the
// whole image when smaller), growing at most fourfold from pass to pass: several samples
// per launch spread a pixel's setup over them, and a band that large keeps a GPU busy.
// When a pass would take over kSplitSeconds, it runs in bands of rows of about
// kTargetSeconds each, so each launch stays short (progress, GPU watchdogs). Sampling stops after a
// pass when every sample is taken, when cancellation is asked, when the next pass would end after
// the time limit, or when the estimated relative noise is below the target. A pass
// after which the samples left would make a last pass no larger than it takes them too (at
// most twice its planned samples, its bands then half as tall): the fourfold growth only
// guards the estimate, and each pass costs every pixel its setup again (at 9 samples:
// passes of 1 + 8 instead of 1 + 4 + 4, one setup fewer). Under a stop rule the
// passes stay fourfold, as the points where it is checked. With --checkpoint, which writes
// only between passes, no pass is planned longer than its interval (cap_pass_seconds).
#pragma once

#include <atomic>
#include <functional>
#include <vector>

#include "app/progress.h"
#include "device/device.h"
#include "integrator/render.h"

namespace rt {

class RenderScheduler {
 public:
  static constexpr double kTargetSeconds = 0.15, kSplitSeconds = 0.5;
  static constexpr long kMinBandPixels = 65536;

  // Plans rows [row_begin, row_end) of an image `height` rows tall (row_end < 0: to the
  // last row); a distributed render gives each rank such a tile. row_begin must be a
  // multiple of row_alignment.
  RenderScheduler(int width, int height, int samples, int row_alignment, int row_begin = 0,
                  int row_end = -1);
  // The next pass: bands of rows covering the tile once, each taking the pixels from
  // samples_done() to the same end; empty when every sample is taken.
  std::vector<RenderWork> plan() const;
  // The pass's expected duration from the costs measured so far.
  double estimate_seconds(const std::vector<RenderWork>& pass) const;
  // Records a finished band and its duration; the pass is complete when its bands are.
  void record(const RenderWork& work, double seconds);
  int samples_done() const { return done_; }
  // Keeps the fourfold growth to the last sample (a stop rule checks between passes).
  void keep_checkpoints() { take_rest_ = false; }
  // The film already holds samples [0, sample) (a checkpoint's): the first pass, one sample
  // that measures the costs, starts there.
  void start_at(int sample) { done_ = sample; }
  // Plans no pass expected to last over `seconds` (but at least one sample of the tile),
  // and takes no last pass together with the one before it past that: a checkpoint, written
  // between passes, then comes within about `seconds` of being due.
  void cap_pass_seconds(double seconds) { cap_seconds_ = seconds; }

 private:
  int width_, height_, samples_, align_, row_begin_, row_end_;
  int done_ = 0;
  int last_pass_samples_ = 1;
  bool measured_ = false;
  bool take_rest_ = true;
  double cap_seconds_ = 0;        // 0: passes as long as the target makes them.
  std::vector<double> row_cost_;  // Seconds per sample of each row, as last measured.
};

// Renders the camera of `flat` on `device`, with the kernel `kernel` configures, under the
// policy above. `cancel`, when set,
// stops sampling at the end of the current pass (RenderResult::cancelled). *load_info
// receives what loading the scene cost. Throws std::runtime_error (one line) on a device
// failure.
// A render continued from a saved film, and what runs between its passes.
struct PassHooks {
  int start_sample = 0;  // The film holds samples [0, start_sample).
  // render_camera: the saved film to load after device.load (RenderDevice::write_film).
  const std::vector<PixelAccum>* accum = nullptr;
  const std::vector<PrimaryInfo>* primary = nullptr;
  // Called after each pass that more passes follow, with the samples taken, the film on the
  // device (a checkpoint reads it there).
  std::function<void(int samples_done)> after_pass;
  // When positive, no pass is planned longer than this (RenderScheduler::cap_pass_seconds),
  // so after_pass runs at least about that often.
  double pass_seconds = 0;
};

RenderResult render_camera(RenderDevice& device, const FlatScene& flat, const KernelConfig& kernel,
                           Progress& progress, const StopRule& stop = StopRule(),
                           const std::atomic<bool>* cancel = nullptr,
                           DeviceLoadInfo* load_info = nullptr, const PassHooks* hooks = nullptr);

// The pass loop of render_camera for rows [row_begin, row_end) of the camera `device` has
// loaded (the film of those rows empty): takes every sample, or stops by `stop`/`cancel`.
// Returns the samples per pixel taken; the film stays on the device.
int sample_rows(RenderDevice& device, const Camera& cam, int row_begin, int row_end,
                Progress& progress, const StopRule& stop = StopRule(),
                const std::atomic<bool>* cancel = nullptr, bool* cancelled = nullptr,
                const PassHooks* hooks = nullptr);

}  // namespace rt
