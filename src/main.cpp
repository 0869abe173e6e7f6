// raytracer: renders every camera of a scene file to PNG on an OpenCL device or with the
// CPU reference renderer.
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <chrono>
#include <cmath>

#include "cli.h"
#include "errors.h"
#include "moments.h"
#include "output_check.h"
#include "png_io.h"
#include "render.h"
#include "render_cl.h"

namespace {

double ms_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t).count();
}

int run(const rt::CliOptions& opt) {
  if (opt.list_devices) return rt::list_cl_devices(stdout) ? 0 : 1;
  auto t0 = std::chrono::steady_clock::now();
  rt::SceneDesc scene = rt::load_scene(opt.scene, opt.load);
  double load_ms = ms_since(t0);
  if (!opt.quiet)
    for (const auto& w : scene.warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
  if (opt.camera >= static_cast<int>(scene.cameras.size()))
    throw rt::input_error(opt.scene, "Cameras", "no camera " + std::to_string(opt.camera) +
                                                    " (the file has " +
                                                    std::to_string(scene.cameras.size()) + ")");
  rt::check_outputs(scene, opt.camera, opt.output_dir, opt.moments);
  if (opt.resolution_scale != 1.0)
    for (rt::CameraDesc& cam : scene.cameras) {
      // The near plane is untouched, so the view stays the same at a different pixel count.
      cam.width = std::max(1, static_cast<int>(std::lround(cam.width * opt.resolution_scale)));
      cam.height = std::max(1, static_cast<int>(std::lround(cam.height * opt.resolution_scale)));
    }
  rt::FlatScene flat = rt::flatten_scene(scene, opt.render);
  std::unique_ptr<rt::ClRenderer> cl;
  if (opt.device != rt::Device::kCpu) {
    std::string why;
    cl = rt::ClRenderer::create(opt.cl_device, opt.kernel_cache, &why);
    if (!cl) {
      if (opt.device == rt::Device::kOpenCl) throw std::runtime_error("OpenCL: " + why);
      if (!opt.quiet)
        std::fprintf(stderr, "notice: no usable OpenCL device (%s); using the CPU reference\n",
                     why.c_str());
    }
  }
  for (int c = 0; c < static_cast<int>(scene.cameras.size()); ++c) {
    if (opt.camera >= 0 && c != opt.camera) continue;
    rt::set_camera(flat, scene, c, opt.render);
    const rt::CameraDesc& cam = scene.cameras[c];
    const Camera& fc = flat.header.camera;
    rt::Progress progress(rt::Progress::wanted(opt.quiet), cam.image_name,
                          static_cast<uint64_t>(fc.width) * fc.height * fc.samples);
    rt::RenderResult r;
    rt::ClTimings clt;
    if (cl) {
      r = cl->render(flat, opt.generic_kernel, progress, &clt, opt.render.stop);
    } else {
      r = rt::render_cpu(flat, opt.threads, progress, opt.render.stop);
    }
    progress.finish();
    if (uint64_t bad = r.nonfinite())
      std::fprintf(stderr, "warning: %s: %llu samples gave NaN or infinite radiance (left out)\n",
                   cam.image_name.c_str(), static_cast<unsigned long long>(bad));
    std::filesystem::path out = std::filesystem::path(opt.output_dir) / cam.image_name;
    rt::write_png(out.string(), rt::to_8bit(r.width, r.height, r.rgb()));
    if (opt.moments) {
      rt::MomentInfo info{opt.render.seed, r.spp,
                          opt.render.filter == RT_FILTER_GAUSSIAN ? "gaussian" : "box",
                          cl ? cl->device_name() : "cpu-reference", opt.scene, c};
      rt::write_moments(rt::moments_path_for(out.string()), rt::moments_from_render(r, info));
    }
    if (opt.stats) {
      std::fprintf(stderr,
                   "stats: %s: device %s | load %.1f ms | bvh %.1f ms (%zu nodes, %zu triangles, "
                   "%zu instances, depth top %d / mesh %d) | kernel compile %.1f ms%s | render "
                   "%.3f s | %d spp | %.3f Msamples/s | %.3f Mrays/s | features 0x%x\n",
                   out.string().c_str(), cl ? cl->device_name().c_str() : "cpu-reference",
                   load_ms, flat.stats.bvh_build_ms, flat.stats.nodes, flat.stats.triangles,
                   flat.stats.instances, flat.stats.tlas_depth, flat.stats.max_blas_depth,
                   clt.compile_ms, clt.cache_hit ? " (cache hit)" : "", r.seconds, r.spp,
                   r.samples / r.seconds * 1e-6, r.rays / r.seconds * 1e-6,
                   static_cast<unsigned>(flat.header.features));
      if (scene.degenerate_triangles)
        std::fprintf(stderr, "stats: degenerate triangles skipped: %d\n", scene.degenerate_triangles);
    }
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  rt::CliOptions opt = rt::parse_cli(argc, argv);
  try {
    return run(opt);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "raytracer: error: %s\n", e.what());
    return 1;
  }
}
