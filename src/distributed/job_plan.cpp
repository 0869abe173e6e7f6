#include "distributed/job_plan.h"

#include <algorithm>

#include "app/output_plan.h"
#include "app/render_job.h"

namespace rt {
namespace {

constexpr int kTasksPerRank = 4;

int round_up(int v, int m) { return (v + m - 1) / m * m; }

}  // namespace

JobPlan plan_job(const CliOptions& opt, int ranks) {
  JobPlan plan;
  check_job_outputs(opt);
  for (int s = 0; s < static_cast<int>(opt.scenes.size()); ++s) {
    const JobScene scene = load_job_scene(opt.scenes[s], opt, true);
    for (int c : job_cameras(opt, scene)) {
      const CameraDesc& cam = scene.desc.cameras[c];
      plan.images.push_back({s, c, cam.width, cam.height, image_path(opt, scene, c), cam});
    }
  }
  const bool stop_rule = opt.render.stop.time_limit_s > 0 || opt.render.stop.noise_target > 0;
  const int images = static_cast<int>(plan.images.size());
  if (stop_rule) {
    plan.tile_rows = 0;
  } else if (opt.tile_rows > 0) {
    plan.tile_rows = round_up(opt.tile_rows, kTileRowMultiple);
  } else if (images > 0 && images < kTasksPerRank * ranks && ranks > 1) {
    const int per_image = (kTasksPerRank * ranks + images - 1) / images;
    int tallest = 0;
    for (const PlannedImage& im : plan.images) tallest = std::max(tallest, im.height);
    plan.tile_rows = round_up(std::max(1, (tallest + per_image - 1) / per_image), kTileRowMultiple);
  }
  for (int i = 0; i < images; ++i) {
    const PlannedImage& im = plan.images[i];
    const int step = plan.tile_rows > 0 ? plan.tile_rows : im.height;
    for (int r = 0; r < im.height; r += step)
      plan.tasks.push_back({i, im.scene, im.camera, r, std::min(im.height, r + step)});
  }
  return plan;
}

}  // namespace rt
