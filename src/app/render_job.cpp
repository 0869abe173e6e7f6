#include "render_job.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "image/tonemap.h"
#include "io/checkpoint.h"
#include "io/image_output.h"
#include "io/moments.h"
#include "io/partial_mark.h"
#include "io/png_io.h"
#include "util/errors.h"

namespace rt {

JobScene load_job_scene(const std::string& path, const CliOptions& opt, bool print_warnings) {
  const auto t0 = std::chrono::steady_clock::now();
  JobScene s;
  s.path = path;
  s.desc = load_scene(path, opt.load);
  s.load_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  if (print_warnings && !opt.quiet)
    for (const auto& w : s.desc.warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
  check_camera_choice(opt, s);
  if (opt.resolution_scale != 1.0)
    for (CameraDesc& cam : s.desc.cameras) {
      // The near plane is untouched, so the view stays the same at a different pixel count.
      cam.width = std::max(1, static_cast<int>(std::lround(cam.width * opt.resolution_scale)));
      cam.height = std::max(1, static_cast<int>(std::lround(cam.height * opt.resolution_scale)));
    }
  return s;
}

void check_camera_choice(const CliOptions& opt, const JobScene& scene) {
  if (opt.camera >= static_cast<int>(scene.desc.cameras.size()))
    throw input_error(scene.path, "Cameras",
                      "no camera " + std::to_string(opt.camera) + " (the file has " +
                          std::to_string(scene.desc.cameras.size()) + ")");
}

void check_output_dir(const CliOptions& opt) {
  std::error_code ec;
  if (!std::filesystem::exists(opt.output_dir, ec))
    throw std::runtime_error(opt.output_dir + ": output directory does not exist");
  if (!std::filesystem::is_directory(opt.output_dir, ec))
    throw std::runtime_error(opt.output_dir + ": output path is not a directory");
  if (access(opt.output_dir.c_str(), W_OK | X_OK) != 0)
    throw std::runtime_error(opt.output_dir + ": output directory is not writable");
}

std::string image_path(const CliOptions& opt, const JobScene& scene, int camera) {
  return (std::filesystem::path(opt.output_dir) / scene.desc.cameras[camera].image_name).string();
}

std::vector<CameraOutput> camera_outputs(const CliOptions& opt, const CameraDesc& cam,
                                         const std::string& image) {
  std::vector<CameraOutput> files{{image, "image"}};
  if (cam.tonemap && is_exr_path(image))
    files.push_back({tonemap_path_for(image), "tone-mapped image"});
  if (opt.moments) files.push_back({moments_path_for(image), "moments file"});
  files.push_back({checkpoint_path_for(image), "checkpoint", true});
  return files;
}

std::vector<int> job_cameras(const CliOptions& opt, const JobScene& scene) {
  std::vector<int> cameras;
  for (int c = 0; c < static_cast<int>(scene.desc.cameras.size()); ++c) {
    if (opt.camera >= 0 && c != opt.camera) continue;
    if (opt.skip_existing || opt.resume) {
      const std::string image = image_path(opt, scene, c);
      std::string why;  // The first partial output; empty when one is missing.
      bool complete = true;
      for (const CameraOutput& f : camera_outputs(opt, scene.desc.cameras[c], image)) {
        if (f.checkpoint) continue;
        const OutputStatus st = output_status(f.path);
        if (st.state == OutputState::kComplete) continue;
        complete = false;
        if (st.state == OutputState::kPartial) why = f.path + " is partial (" + st.mark + ")";
        break;
      }
      if (complete) continue;
      std::error_code ec;
      if (!why.empty() && !opt.quiet)
        std::fprintf(stderr, "notice: %s: %s\n", why.c_str(),
                     std::filesystem::exists(checkpoint_path_for(image), ec)
                         ? "continuing it from its checkpoint"
                         : "no checkpoint, rendering it again");
    }
    cameras.push_back(c);
  }
  return cameras;
}

DeviceOptions device_options(const CliOptions& opt, int gpu_rank, int threads) {
  DeviceOptions d;
  d.kind = opt.device;
  d.cl_selector = opt.cl_device;
  d.kernel_cache = opt.kernel_cache;
  d.generic_kernel = opt.generic_kernel;
  d.threads = threads;
  d.gpu_rank = gpu_rank;
  return d;
}

// The film's copy in the RenderResult, the float image, the 8-bit image or the EXR's
// encoding (each at most 12 bytes a pixel), and with moments their planes (52 bytes a
// pixel), a copy and the encoding.
uint64_t output_bytes(uint64_t pixels, bool moments) {
  return pixels * (kFilmBytesPerPixel + 12 + 12 + 12 + (moments ? 3 * 60 : 0));
}

void write_outputs(const CliOptions& opt, const std::string& scene_path, int camera,
                   const CameraDesc& cam, const std::string& device_name, const RenderResult& r,
                   const std::string& out, const std::string& samples_mark) {
  const uint64_t bad = samples_mark.empty() ? r.nonfinite() : 0;
  if (bad)
    std::fprintf(stderr, "warning: %s: %llu samples gave NaN or infinite radiance (left out)\n",
                 std::filesystem::path(out).filename().c_str(),
                 static_cast<unsigned long long>(bad));
  write_image(out, r.width, r.height, r.rgb(), opt.quantize, samples_mark);
  // hw5: a camera with <Tonemap> whose image is HDR also gets the photographic operator's
  // 8-bit image of the same film, beside it with the extension .png.
  if (cam.tonemap && is_exr_path(out)) {
    const std::string png = tonemap_path_for(out);
    ImageF film;
    film.width = r.width;
    film.height = r.height;
    film.max_value = 0.0f;
    film.pixels = r.rgb();
    Image8 mapped = TonemapPhotographic(film, cam.tonemap_params);
    mapped.samples_mark = samples_mark;
    write_png(png, mapped);
  }
  if (opt.moments) {
    MomentInfo info{
        opt.render.seed, r.spp,      opt.render.filter == RT_FILTER_GAUSSIAN ? "gaussian" : "box",
        device_name,     scene_path, camera,
        samples_mark};
    write_moments(moments_path_for(out), moments_from_render(r, info));
  }
}

}  // namespace rt
