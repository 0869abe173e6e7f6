#include "image_checkpoint.h"

#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "io/partial_mark.h"

namespace rt {

ImageCheckpoint::ImageCheckpoint(const CliOptions& opt, const JobScene& scene, int camera,
                                 const PreparedScene& prepared, const RenderDevice& device,
                                 bool bands_allowed)
    : opt_(opt),
      scene_(scene),
      camera_(camera),
      prepared_(prepared),
      device_name_(device.name()),
      image_(image_path(opt, scene, camera)),
      path_(checkpoint_path_for(image_)) {
  const CameraDesc& cam = scene.desc.cameras[camera];
  asked_ = opt.render.spp > 0 ? opt.render.spp : cam.samples;
  std::error_code ec;
  if (!(opt.resume || opt.skip_existing) || !std::filesystem::exists(path_, ec)) return;
  saved_ = read_checkpoint(path_);
  const std::string diff = key_difference(saved_.key, key());
  if (!diff.empty())
    throw std::runtime_error(path_ + ": not continued: " + diff +
                             " (render without --resume to start again)");
  if (!saved_.row_spp.empty() && !bands_allowed)
    throw std::runtime_error(path_ +
                             ": not continued here: its bands of rows hold different sample "
                             "counts (a distributed render stopped); continue it under mpirun");
  hooks_.start_sample = saved_.spp;
  hooks_.accum = &saved_.accum;
  hooks_.primary = &saved_.primary;
}

// Everything that changes the film's bytes, each field a line of the checkpoint's header.
// The device's name is part of it: the OpenCL and CPU films of a scene agree bit for bit
// (tests/course/cl_vs_cpu.sh), but that is checked per scene, not promised for every device.
const CheckpointKey& ImageCheckpoint::key() {
  if (!key_.empty()) return key_;
  const CameraDesc& cam = scene_.desc.cameras[camera_];
  key_.emplace_back("inputs", files_hash(scene_.desc.inputs));
  key_.emplace_back("camera", std::to_string(camera_));
  key_.emplace_back("resolution", std::to_string(cam.width) + "x" + std::to_string(cam.height));
  key_.emplace_back("samples", std::to_string(asked_));
  const auto& table = device_option_table();
  for (size_t i = 0; i < table.options().size(); ++i)
    if (table.show_fn(i))
      key_.emplace_back(table.options()[i].names[0], table.show_fn(i)(opt_.render));
  // The switches, which the table cannot show (a flag has no value text).
  const RenderOptions& o = opt_.render;
  std::string flags;
  for (const auto& [on, name] : {std::pair{o.cull_back_faces, "--cull-back-faces"},
                                 {o.background_on_secondary_miss, "--background-on-secondary-miss"},
                                 {!o.use_scene_epsilon, "--no-scene-epsilon"},
                                 {o.fast_math, "--fast-math"}})
    if (on) flags += std::string(flags.empty() ? "" : ",") + name;
  key_.emplace_back("switches", flags.empty() ? "none" : flags);
  key_.emplace_back("arithmetic", prepared_.kernel.double_precision ? "double" : "float");
  key_.emplace_back("bvh", std::to_string(prepared_.kernel.bvh_width) + "-wide, " +
                               std::to_string(opt_.render.bvh.bins) + " bins, leaf " +
                               std::to_string(opt_.render.bvh.max_leaf));
  key_.emplace_back("device", device_name_);
  key_.emplace_back("film", std::to_string(sizeof(PixelAccum)) + "+" +
                                std::to_string(sizeof(PrimaryInfo)) + " bytes a pixel");
  return key_;
}

const PassHooks* ImageCheckpoint::hooks(RenderDevice& device) {
  last_save_ = std::chrono::steady_clock::now();
  if (opt_.checkpoint_s > 0) {
    hooks_.pass_seconds = opt_.checkpoint_s;
    hooks_.after_pass = [this, &device](int spp) {
      const auto now = std::chrono::steady_clock::now();
      const double since = std::chrono::duration<double>(now - last_save_).count();
      if (since < opt_.checkpoint_s) return;
      save(device, spp, since);
      last_save_ = std::chrono::steady_clock::now();
    };
  }
  return &hooks_;
}

void ImageCheckpoint::save(RenderDevice& device, int spp, double since_last) {
  const CameraDesc& cam = scene_.desc.cameras[camera_];
  RenderResult r;
  r.width = cam.width;
  r.height = cam.height;
  r.spp = spp;
  device.read_accum(&r.accum);
  device.read_primary(&r.primary);
  write(r, true);
  if (opt_.stats)
    std::fprintf(
        stderr,
        "stats: checkpoint: %s at %d of %d samples per pixel, %.3f s after the last or the start\n",
        path_.c_str(), spp, asked_, since_last);
}

// The checkpoint first: an image marked partial has the film that continues it whenever
// checkpoints are asked for (--checkpoint, --resume, or a render continued from one).
void ImageCheckpoint::write(const RenderResult& r, bool partial) {
  const CameraDesc& cam = scene_.desc.cameras[camera_];
  if (partial && keeps_checkpoints()) {
    Checkpoint c;
    c.key = key();
    c.spp = r.spp;
    c.accum = r.accum;
    c.primary = r.primary;
    write_checkpoint(path_, c);
  }
  write_outputs(opt_, scene_.path, camera_, cam, device_name_, r, image_,
                partial ? samples_mark_text(r.spp, asked_) : "");
}

std::string ImageCheckpoint::finish(const RenderResult& r, bool interrupted) {
  const bool partial = interrupted && r.spp < asked_;
  write(r, partial);
  if (partial && keeps_checkpoints()) return path_;
  std::error_code ec;
  std::filesystem::remove(path_, ec);  // Done with, or stale (not this image's film).
  return "";
}

}  // namespace rt
