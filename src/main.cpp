// raytracer: renders every camera of a scene file to an image (PNG, or EXR by extension) on
// the device chosen by --device, through the one scheduler.
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "cli.h"
#include "device/cl/cl_platform.h"
#include "device/device.h"
#include "errors.h"
#include "image/tonemap.h"
#include "integrator/render_scheduler.h"
#include "interrupt.h"
#include "io/image_output.h"
#include "io/moments.h"
#include "io/png_io.h"
#include "output_check.h"

namespace {

double ms_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t).count();
}

// Host bytes the outputs of one image take besides the device's film: the film's copy in the
// RenderResult, the float image, the 8-bit image or the EXR's encoding (each at most 12 bytes a
// pixel), and with moments their planes (52 bytes a pixel), a copy and the encoding.
uint64_t output_bytes(uint64_t pixels, bool moments) {
  return pixels * (rt::kFilmBytesPerPixel + 12 + 12 + 12 + (moments ? 3 * 60 : 0));
}

int run(const rt::CliOptions& opt) {
  if (opt.list_devices) return rt::list_cl_devices(stdout) ? 0 : 1;
  auto t0 = std::chrono::steady_clock::now();
  rt::SceneDesc scene = rt::load_scene(opt.scene, opt.load);
  double load_ms = ms_since(t0);
  if (!opt.quiet)
    for (const auto& w : scene.warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
  if (opt.camera >= static_cast<int>(scene.cameras.size()))
    throw rt::input_error(opt.scene, "Cameras",
                          "no camera " + std::to_string(opt.camera) + " (the file has " +
                              std::to_string(scene.cameras.size()) + ")");
  rt::check_outputs(scene, opt.camera, opt.output_dir, opt.moments);
  if (opt.resolution_scale != 1.0)
    for (rt::CameraDesc& cam : scene.cameras) {
      // The near plane is untouched, so the view stays the same at a different pixel count.
      cam.width = std::max(1, static_cast<int>(std::lround(cam.width * opt.resolution_scale)));
      cam.height = std::max(1, static_cast<int>(std::lround(cam.height * opt.resolution_scale)));
    }
  rt::FlatScene flat = rt::flatten_scene(scene, opt.render);
  rt::DeviceOptions device_options;
  device_options.kind = opt.device;
  device_options.cl_selector = opt.cl_device;
  device_options.kernel_cache = opt.kernel_cache;
  device_options.generic_kernel = opt.generic_kernel;
  device_options.threads = opt.threads;
  std::string notice;
  std::unique_ptr<rt::RenderDevice> device = rt::create_device(device_options, &notice);
  if (!notice.empty() && !opt.quiet) std::fprintf(stderr, "notice: %s\n", notice.c_str());
  std::vector<int> cameras;
  for (int c = 0; c < static_cast<int>(scene.cameras.size()); ++c)
    if (opt.camera < 0 || c == opt.camera) cameras.push_back(c);
  // Every image's memory is checked before the first render starts.
  for (int c : cameras) {
    rt::set_camera(flat, scene, c, opt.render);
    const Camera& fc = flat.header.camera;
    try {
      device->check_memory(flat,
                           output_bytes(static_cast<uint64_t>(fc.width) * fc.height, opt.moments));
    } catch (const std::exception& e) {
      throw std::runtime_error(scene.cameras[c].image_name + ": " + e.what());
    }
  }
  for (size_t k = 0; k < cameras.size(); ++k) {
    const int c = cameras[k];
    rt::set_camera(flat, scene, c, opt.render);
    const rt::CameraDesc& cam = scene.cameras[c];
    const Camera& fc = flat.header.camera;
    rt::Progress progress(rt::Progress::wanted(opt.quiet), cam.image_name,
                          static_cast<uint64_t>(fc.width) * fc.height * fc.samples);
    rt::DeviceLoadInfo load;
    rt::RenderResult r =
        rt::render_camera(*device, flat, progress, opt.render.stop, &rt::stop_requested(), &load);
    progress.finish();
    if (uint64_t bad = r.nonfinite())
      std::fprintf(stderr, "warning: %s: %llu samples gave NaN or infinite radiance (left out)\n",
                   cam.image_name.c_str(), static_cast<unsigned long long>(bad));
    std::filesystem::path out = std::filesystem::path(opt.output_dir) / cam.image_name;
    rt::write_image(out.string(), r.width, r.height, r.rgb(), opt.quantize);
    // hw5: a camera with <Tonemap> whose image is HDR also gets the photographic
    // operator's 8-bit image of the same film, beside it with the extension .png.
    if (cam.tonemap && rt::is_exr_path(out.string())) {
      std::filesystem::path png = out;
      png.replace_extension(".png");
      rt::ImageF film;
      film.width = r.width;
      film.height = r.height;
      film.max_value = 0.0f;
      film.pixels = r.rgb();
      rt::write_png(png.string(), rt::TonemapPhotographic(film, cam.tonemap_params));
    }
    if (opt.moments) {
      rt::MomentInfo info{
          opt.render.seed, r.spp,     opt.render.filter == RT_FILTER_GAUSSIAN ? "gaussian" : "box",
          device->name(),  opt.scene, c};
      rt::write_moments(rt::moments_path_for(out.string()), rt::moments_from_render(r, info));
    }
    if (opt.stats) {
      std::fprintf(stderr,
                   "stats: %s: device %s | load %.1f ms | bvh %.1f ms (%zu nodes, %zu triangles, "
                   "%zu instances, depth top %d / mesh %d) | kernel compile %.1f ms%s | render "
                   "%.3f s | %d spp | %.3f Msamples/s | %.3f Mrays/s | features 0x%x\n",
                   out.string().c_str(), device->name().c_str(), load_ms, flat.stats.bvh_build_ms,
                   flat.stats.nodes, flat.stats.triangles, flat.stats.instances,
                   flat.stats.tlas_depth, flat.stats.max_blas_depth, load.compile_ms,
                   load.cache_hit ? " (cache hit)" : "", r.seconds, r.spp,
                   r.samples / r.seconds * 1e-6, r.rays / r.seconds * 1e-6,
                   static_cast<unsigned>(flat.header.features));
      if (scene.degenerate_triangles)
        std::fprintf(stderr, "stats: degenerate triangles skipped: %d\n",
                     scene.degenerate_triangles);
    }
    if (rt::stop_requested().load()) {
      std::fprintf(stderr, "raytracer: interrupted: %s written with %d of %d samples per pixel%s\n",
                   out.string().c_str(), r.spp, fc.samples,
                   k + 1 < cameras.size() ? "; the cameras after it were not rendered" : "");
      return rt::kInterruptedExitStatus;
    }
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  rt::CliOptions opt = rt::parse_cli(argc, argv);
  rt::install_interrupt_handlers(opt.quiet);
  try {
    return run(opt);
  } catch (const std::bad_alloc&) {
    // The memory check runs before every large allocation; this is the fallback.
    std::fprintf(stderr, "raytracer: error: out of memory\n");
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "raytracer: error: %s\n", e.what());
    return 1;
  }
}
