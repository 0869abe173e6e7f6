#include "distributed/tile_worker.h"

#include <chrono>
#include <stdexcept>

#include "app/image_checkpoint.h"
#include "integrator/render_scheduler.h"

namespace rt {

TileWorker::TileWorker(const CliOptions& opt, int gpu_rank, int threads) : opt_(opt) {
  std::string notice;  // Rank 0 has printed the notice of its own device already.
  device_ = create_device(device_options(opt, gpu_rank, threads), &notice);
}

TileResult TileWorker::render(const TileTask& task) {
  const auto t0 = std::chrono::steady_clock::now();
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
    resume_ = ImageCheckpoint(opt_, scene_, task.camera, prepared_, *device_).resume_only();
    if (resume_.accum) device_->write_film(*resume_.accum, *resume_.primary);
    resume_.accum = nullptr;
    resume_.primary = nullptr;
    camera_ = task.camera;
  }
  const Camera& cam = prepared_.flat.header.camera;
  const int align = device_->row_alignment();
  if (task.row_begin % align != 0)
    throw std::runtime_error(name + ": a tile starting at row " + std::to_string(task.row_begin) +
                             " is not aligned to the device's " + std::to_string(align) +
                             "-row work-groups");
  Progress quiet(false, name, 0);
  TileResult out;
  out.task = task;
  out.spp = sample_rows(*device_, cam, task.row_begin, task.row_end, quiet,
                        camera_stop_rule(opt_.render.stop, scene_.desc.cameras[task.camera]),
                        nullptr, nullptr, &resume_);
  device_->read_accum(&accum_);
  device_->read_primary(&primary_);
  const size_t first = static_cast<size_t>(task.row_begin) * cam.width;
  const size_t last = static_cast<size_t>(task.row_end) * cam.width;
  out.accum.assign(accum_.begin() + first, accum_.begin() + last);
  out.primary.assign(primary_.begin() + first, primary_.begin() + last);
  out.busy_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace rt
