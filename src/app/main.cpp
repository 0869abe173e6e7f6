// raytracer: renders every camera of each scene file given to an image (PNG, or EXR by
// extension) on the device chosen by --device, through the one scheduler; under mpirun (a
// build with MPI) the distributed driver spreads the images over the ranks instead.
#include <chrono>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>

#include "backface_notice.h"
#include "cli.h"
#include "device/cl/cl_platform.h"
#include "device/device.h"
#include "image_checkpoint.h"
#include "integrator/render_scheduler.h"
#include "interrupt.h"
#include "job_count.h"
#include "output_plan.h"
#include "progress.h"
#include "render_job.h"
#ifdef RT_WITH_MPI
#include "distributed/mpi_render.h"
#endif

namespace {

void print_stats(const std::string& out, const rt::RenderDevice& device, const rt::JobScene& s,
                 const rt::PreparedScene& prepared, const rt::DeviceLoadInfo& load,
                 const rt::RenderResult& r) {
  const rt::FlatScene& flat = prepared.flat;
  std::fprintf(
      stderr,
      "stats: %s: device %s | load %.1f ms | bvh %.1f ms (%zu %d-wide nodes, %zu triangles, "
      "%zu instances, depth top %d / mesh %d) | camera frame %.2f ms (top levels built %d) | "
      "kernel compile "
      "%.1f ms%s | upload %.1f ms (%.0f MiB shared) | render "
      "%.3f s | %d spp | %.3f Msamples/s | %.3f Mrays/s | features 0x%x\n",
      out.c_str(), device.name().c_str(), s.load_ms, flat.stats.bvh_build_ms, flat.stats.nodes,
      prepared.kernel.bvh_width, flat.stats.triangles, flat.stats.instances, flat.stats.tlas_depth,
      flat.stats.max_blas_depth, flat.stats.place_ms, flat.stats.top_levels_built, load.compile_ms,
      load.cache_hit ? " (cache hit)" : "", load.upload_ms, load.shared_bytes / 1048576.0,
      r.seconds, r.spp, r.samples / r.seconds * 1e-6, r.rays / r.seconds * 1e-6,
      static_cast<unsigned>(flat.header.features));
  // The kernel's options, so that anyone can compile the same kernel offline
  // (tests/gpu/gpu_kernels.py reads them): the device's own on OpenCL, else those any
  // OpenCL device would start from for this camera.
  if (!load.build_options.empty())
    std::fprintf(stderr, "stats: %s: kernel build options %s\n", out.c_str(),
                 load.build_options.c_str());
  else
    std::fprintf(stderr, "stats: %s: kernel defines %s\n", out.c_str(),
                 rt::kernel_defines(static_cast<int>(flat.header.features),
                                    rt::sized_for_scene(prepared.kernel, flat))
                     .c_str());
  if (s.desc.degenerate_triangles)
    std::fprintf(stderr, "stats: degenerate triangles skipped: %d\n", s.desc.degenerate_triangles);
}

// Where the job stands, for the progress line's "[k/n]": images started, and the job's
// images (counted from the files' text ahead, corrected as each file is loaded).
struct JobCount {
  int started = 0, total = 0;
  bool back_face_notice_given = false;
};

// Renders the cameras of one scene file; returns false when an interrupt ended sampling.
bool render_scene(const rt::CliOptions& opt, const rt::JobScene& s,
                  std::unique_ptr<rt::RenderDevice>& device, bool last_scene, JobCount& job) {
  const std::vector<int> cameras = rt::job_cameras(opt, s);
  const bool live = rt::Progress::wanted(opt.quiet);
  if (cameras.empty()) return true;
  const bool new_device = !device;
  if (new_device) {
    std::string notice;
    rt::show_status(live, "opening the device...");
    device = rt::create_device(rt::device_options(opt, 0, opt.threads), &notice);
    rt::clear_status(live);
    if (!notice.empty() && !opt.quiet) std::fprintf(stderr, "notice: %s\n", notice.c_str());
  }
  std::string notice;
  rt::show_status(live, "building the BVH of " + s.path + "...");
  rt::PreparedScene prepared = rt::prepare_for_device(s.desc, opt.render, *device, &notice);
  rt::clear_status(live);
  if (new_device && !notice.empty() && !opt.quiet)
    std::fprintf(stderr, "notice: %s\n", notice.c_str());
  const rt::FlatScene& flat = prepared.flat;
  // Every image's memory is checked before the first render starts, each camera's arrays
  // estimated from the scene's (they are placed only to be rendered).
  for (int c : cameras) {
    const rt::CameraDesc& cam = s.desc.cameras[c];
    try {
      device->check_memory(rt::camera_memory_need(
          prepared, s.desc, c,
          rt::output_bytes(static_cast<uint64_t>(cam.width) * cam.height, opt.moments)));
    } catch (const std::exception& e) {
      throw std::runtime_error(cam.image_name + ": " + e.what());
    }
  }
  // Every checkpoint --resume continues is checked before the first render, as memory is.
  for (int c : cameras) rt::ImageCheckpoint(opt, s, c, prepared, *device);
  for (size_t k = 0; k < cameras.size(); ++k) {
    const int c = cameras[k];
    try {
      rt::prepare_camera(prepared, s.desc, c);  // Also checks the camera's frame.
    } catch (const std::invalid_argument& e) {
      throw std::runtime_error(s.path + ": Cameras > Camera " + std::to_string(c) + ": " +
                               e.what());
    }
    rt::ImageCheckpoint checkpoint(opt, s, c, prepared, *device);
    const Camera& fc = flat.header.camera;
    const std::string label = "[" + std::to_string(++job.started) + "/" +
                              std::to_string(job.total) + "] " + s.desc.cameras[c].image_name;
    rt::show_status(live, label + ": preparing the device...");
    rt::Progress progress(live, label, static_cast<uint64_t>(fc.width) * fc.height, fc.samples);
    progress.start_at(checkpoint.start_sample());
    rt::DeviceLoadInfo load;
    rt::RenderResult r = rt::render_camera(*device, flat, prepared.kernel, progress,
                                           rt::camera_stop_rule(opt.render.stop, s.desc.cameras[c]),
                                           &rt::stop_requested(), &load, checkpoint.hooks(*device));
    progress.finish();
    const std::string out = rt::image_path(opt, s, c);
    const std::string saved = checkpoint.finish(r, rt::stop_requested().load());
    rt::print_wrote(live, out, r.spp, r.seconds);
    if (!opt.quiet && !opt.render.cull_back_faces && !job.back_face_notice_given) {
      const std::string text = rt::back_face_notice(rt::back_face_share(fc, r.primary));
      job.back_face_notice_given = !text.empty();
      if (!text.empty()) std::fprintf(stderr, "notice: %s: %s\n", out.c_str(), text.c_str());
    }
    if (opt.stats) print_stats(out, *device, s, prepared, load, r);
    if (rt::stop_requested().load()) {
      std::fprintf(
          stderr, "raytracer: interrupted: %s written with %d of %d samples per pixel%s%s%s\n",
          out.c_str(), r.spp, fc.samples, saved.empty() ? "" : " and its checkpoint ",
          saved.empty() ? "" : saved.c_str(),
          k + 1 < cameras.size() || !last_scene ? "; the cameras after it were not rendered" : "");
      return false;
    }
  }
  return true;
}

int run(const rt::CliOptions& opt) {
  if (opt.list_devices) return rt::list_cl_devices(stdout) ? 0 : 1;
  rt::check_output_dir(opt);
#ifdef RT_WITH_MPI
  if (rt::launched_by_mpi()) return rt::render_distributed(opt);
#endif
  std::unique_ptr<rt::RenderDevice> device;
  const bool live = rt::Progress::wanted(opt.quiet);
  rt::enable_status_reports(live);  // The OpenCL kernel compile says so (cl_program.cpp).
  // Every scene file read (lightly) and every output checked before the first renders.
  rt::show_status(live, "checking the scene files and their outputs...");
  rt::check_job_outputs(opt);
  JobCount job;
  std::vector<int> counted(opt.scenes.size());
  for (size_t i = 0; i < opt.scenes.size(); ++i) {
    counted[i] = opt.camera >= 0 ? 1 : rt::count_scene_cameras(opt.scenes[i]);
    job.total += counted[i];
  }
  for (size_t i = 0; i < opt.scenes.size(); ++i) {
    rt::show_status(live, "loading " + opt.scenes[i] + "...");
    // Warnings printed after the status is cleared, so they start a line of their own.
    const rt::JobScene s = rt::load_job_scene(opt.scenes[i], opt, false);
    rt::clear_status(live);
    if (!opt.quiet)
      for (const auto& w : s.desc.warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
    job.total += static_cast<int>(rt::job_cameras(opt, s).size()) - counted[i];
    if (!render_scene(opt, s, device, i + 1 == opt.scenes.size(), job))
      return rt::kInterruptedExitStatus;
  }
  rt::clear_status(live);
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
    rt::clear_status(rt::Progress::wanted(opt.quiet));
    std::fprintf(stderr, "raytracer: error: %s\n", e.what());
    return 1;
  }
}
