// What every rank does with a task, whatever the transport: renders a band of rows of one
// image on its own device, through the one scheduler, and hands back that band's film.
#pragma once

#include <chrono>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "app/cli.h"
#include "app/render_job.h"
#include "device/device.h"
#include "distributed/job_plan.h"
#include "integrator/render_scheduler.h"
#include "io/checkpoint.h"

namespace rt {

// A rendered band: the film of rows [task.row_begin, task.row_end).
struct TileResult {
  TileTask task;
  // Samples each row of the band holds: every sample asked, fewer under a stop rule, or
  // where the job's stop (stop_requested) ended sampling; a band continued from a
  // distributed render's checkpoint may start its rows at different counts.
  std::vector<int> row_spp;
  bool stopped = false;     // The job's stop ended it before its last sample.
  double busy_s = 0;        // Wall time the rank spent on the task, loading the scene included.
  uint64_t back_faces = 0;  // Its pixels whose camera ray first hit a back face.
  CheckpointKey key;        // The key of the image's checkpoint, as this rank makes it.
  std::vector<PixelAccum> accum;
  std::vector<PrimaryInfo> primary;
};

// Called between passes with the band so far (TileResult::row_spp at the counts taken).
using TileSnapshot = std::function<void(const TileResult&)>;

class TileWorker {
 public:
  // Opens the device (`gpu_rank` picks among several GPUs, `threads` the CPU reference's
  // threads); throws one line when it cannot.
  TileWorker(const CliOptions& opt, int gpu_rank, int threads);
  std::string device_name() const { return device_->name(); }
  // Renders `task`; the scene file is loaded and prepared when it changes, and the device
  // reloaded when the camera changes (tiles of one image share the film). Sampling stops
  // at the end of a pass once stop_requested() is set. With --checkpoint S, `snapshot`
  // gets the band every S seconds between passes; `each_pass` runs between any two passes
  // (a rank looks for rank 0's stop there). Throws one line.
  TileResult render(const TileTask& task, const TileSnapshot& snapshot = {},
                    const std::function<void()>& each_pass = {});

 private:
  TileResult band(const TileTask& task, const std::vector<int>& rows, bool stopped);

  const CliOptions& opt_;
  std::unique_ptr<RenderDevice> device_;
  int scene_index_ = -1, camera_ = -1;
  JobScene scene_;
  PreparedScene prepared_;
  // Samples each row of the loaded camera's film holds before its tasks run: its
  // checkpoint's (the film loaded), else 0.
  std::vector<int> start_rows_;
  CheckpointKey key_;
  std::vector<PixelAccum> accum_;
  std::vector<PrimaryInfo> primary_;
};

}  // namespace rt
