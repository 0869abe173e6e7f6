#include "distributed/tile_worker.h"

#include <algorithm>
#include <stdexcept>

#include "app/backface_notice.h"
#include "app/image_checkpoint.h"
#include "app/interrupt.h"
#include "integrator/render_scheduler.h"

namespace rt {

TileWorker::TileWorker(const CliOptions& opt, int gpu_rank, int threads) : opt_(opt) {
  std::string notice;  // Rank 0 has printed the notice of its own device already.
  device_ = create_device(device_options(opt, gpu_rank, threads), &notice);
}

TileResult TileWorker::band(const TileTask& task, const std::vector<int>& rows, bool stopped) {
  const Camera& cam = prepared_.flat.header.camera;
  device_->read_accum(&accum_);
  device_->read_primary(&primary_);
  const size_t first = static_cast<size_t>(task.row_begin) * cam.width;
  const size_t last = static_cast<size_t>(task.row_end) * cam.width;
  TileResult out;
  out.task = task;
  out.row_spp = rows;
  out.stopped = stopped;
  out.key = key_;
  out.accum.assign(accum_.begin() + first, accum_.begin() + last);
  out.primary.assign(primary_.begin() + first, primary_.begin() + last);
  out.back_faces = back_face_pixels(cam, primary_, task.row_begin, task.row_end);
  return out;
}

TileResult TileWorker::render(const TileTask& task, const TileSnapshot& snapshot,
                              const std::function<void()>& each_pass) {
  using Clock = std::chrono::steady_clock;
  const auto t0 = Clock::now();
  if (task.scene != scene_index_) {
    scene_index_ = -1;
    scene_ = load_job_scene(opt_.scenes.at(task.scene), opt_, false);
    std::string notice;  // Rank 0 prints the notice of its own device.
    prepared_ = prepare_for_device(scene_.desc, opt_.render, *device_, &notice);
    scene_index_ = task.scene;
    camera_ = -1;
  }
  const std::string& name = scene_.desc.cameras.at(task.camera).image_name;
  if (task.camera != camera_) {
    camera_ = -1;
    const CameraDesc& c = scene_.desc.cameras[task.camera];
    try {
      // Rank 0 holds the whole image's outputs; this rank the film and one band's copy.
      device_->check_memory(
          camera_memory_need(prepared_, scene_.desc, task.camera,
                             2 * static_cast<uint64_t>(c.width) * c.height * kFilmBytesPerPixel));
    } catch (const std::exception& e) {
      throw std::runtime_error(name + ": " + e.what());
    }
    prepare_camera(prepared_, scene_.desc, task.camera);
    device_->load(prepared_.flat, prepared_.kernel);
    // A checkpoint's film, whole: this rank's tiles of the image continue their rows of it.
    ImageCheckpoint checkpoint(opt_, scene_, task.camera, prepared_, *device_, true);
    const PassHooks resume = checkpoint.resume_only();
    if (resume.accum) device_->write_film(*resume.accum, *resume.primary);
    start_rows_ = checkpoint.saved_rows();
    if (start_rows_.empty()) start_rows_.assign(c.height, resume.start_sample);
    if (static_cast<int>(start_rows_.size()) != c.height)
      throw std::runtime_error(name + ": its checkpoint's rows are not the image's");
    key_ = checkpoint.key();
    camera_ = task.camera;
  }
  const Camera& cam = prepared_.flat.header.camera;
  const int align = device_->row_alignment();
  const StopRule stop = camera_stop_rule(opt_.render.stop, scene_.desc.cameras[task.camera]);
  Progress quiet(false, name, 0);
  std::vector<int> rows(start_rows_.begin() + task.row_begin, start_rows_.begin() + task.row_end);
  auto last_snapshot = Clock::now();
  // Rows that start at the same count are sampled together (all of the band, but for a
  // band continued from a distributed render's checkpoint).
  for (int y = task.row_begin, end; y < task.row_end && !stop_requested().load(); y = end) {
    for (end = y + 1; end < task.row_end && start_rows_[end] == start_rows_[y];) ++end;
    if (y % align != 0)
      throw std::runtime_error(name + ": a tile starting at row " + std::to_string(y) +
                               " is not aligned to the device's " + std::to_string(align) +
                               "-row work-groups");
    PassHooks hooks;
    hooks.start_sample = start_rows_[y];
    hooks.after_pass = [&, y, end](int done) {
      if (each_pass) each_pass();
      if (!snapshot || opt_.checkpoint_s <= 0 ||
          std::chrono::duration<double>(Clock::now() - last_snapshot).count() < opt_.checkpoint_s)
        return;
      std::fill(rows.begin() + (y - task.row_begin), rows.begin() + (end - task.row_begin), done);
      snapshot(band(task, rows, false));
      last_snapshot = Clock::now();
    };
    const int spp =
        sample_rows(*device_, cam, y, end, quiet, stop, &stop_requested(), nullptr, &hooks);
    std::fill(rows.begin() + (y - task.row_begin), rows.begin() + (end - task.row_begin), spp);
  }
  const bool stopped =
      stop_requested().load() && *std::min_element(rows.begin(), rows.end()) < cam.samples;
  TileResult out = band(task, rows, stopped);
  out.busy_s = std::chrono::duration<double>(Clock::now() - t0).count();
  return out;
}

}  // namespace rt
