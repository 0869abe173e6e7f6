// What every rank does with a task, whatever the transport: renders a band of rows of one
// image on its own device, through the one scheduler, and hands back that band's film.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "app/cli.h"
#include "app/render_job.h"
#include "device/device.h"
#include "distributed/job_plan.h"
#include "integrator/render_scheduler.h"

namespace rt {

// A rendered band: the film of rows [task.row_begin, task.row_end).
struct TileResult {
  TileTask task;
  int spp = 0;        // Samples per pixel taken (fewer than asked only under a stop rule).
  double busy_s = 0;  // Wall time the rank spent on the task, loading the scene included.
  std::vector<PixelAccum> accum;
  std::vector<PrimaryInfo> primary;
};

class TileWorker {
 public:
  // Opens the device (`gpu_rank` picks among several GPUs, `threads` the CPU reference's
  // threads); throws one line when it cannot.
  TileWorker(const CliOptions& opt, int gpu_rank, int threads);
  std::string device_name() const { return device_->name(); }
  // Renders `task`; the scene file is loaded and prepared when it changes, and the device
  // reloaded when the camera changes (tiles of one image share the film). Throws one line.
  TileResult render(const TileTask& task);

 private:
  const CliOptions& opt_;
  std::unique_ptr<RenderDevice> device_;
  int scene_index_ = -1, camera_ = -1;
  JobScene scene_;
  PreparedScene prepared_;
  PassHooks resume_;  // The samples the loaded camera's checkpoint holds (its film loaded).
  std::vector<PixelAccum> accum_;
  std::vector<PrimaryInfo> primary_;
};

}  // namespace rt
