#include "sweep_run.h"

#include <sys/stat.h>
#include <time.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <stdexcept>

#include "integrator/render_scheduler.h"

namespace sweep {

namespace {

double ProcessCpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// The configuration's options written into the camera it renders; restored on return.
class CameraOverride {
 public:
  CameraOverride(rt::SceneDesc& scene, int camera, int path_flags)
      : cam_(scene.cameras[camera]), saved_(cam_.path_flags) {
    if (path_flags >= 0 && cam_.path_tracing) cam_.path_flags = path_flags;
  }
  ~CameraOverride() { cam_.path_flags = saved_; }

 private:
  rt::CameraDesc& cam_;
  int saved_;
};

rt::RenderDevice* Open(const Config& c, rt::DevicePool& devices) {
  rt::DeviceOptions options;
  options.kind = c.device == "cl" ? rt::Device::kOpenCl : rt::Device::kCpu;
  options.generic_kernel = c.generic;
  std::string why;
  rt::RenderDevice* device = devices.get(options, &why);
  if (!device) throw std::runtime_error(why);
  return device;
}

}  // namespace

Timed Render(rt::SceneDesc& scene, const Config& c, int camera, rt::DevicePool& devices, int reps) {
  CameraOverride use(scene, camera, c.path_flags);
  rt::RenderDevice* device = Open(c, devices);
  std::string notice;  // As the executable prepares it.
  rt::PreparedScene prepared = rt::prepare_for_device(scene, c.opt, *device, &notice);
  rt::prepare_camera(prepared, scene, camera);
  const rt::FlatScene& flat = prepared.flat;
  device->load(flat, prepared.kernel);  // Builds (or finds) the program: not part of the timing.
  rt::Progress quiet(false, "", 0);
  std::vector<Timed> runs;
  for (int k = 0; k < std::max(1, reps); ++k) {
    Timed t;
    t.build_ms = flat.stats.bvh_build_ms;
    const double start = ProcessCpuSeconds();
    t.result = rt::render_camera(*device, flat, prepared.kernel, quiet,
                                 rt::camera_stop_rule(c.opt.stop, scene.cameras[camera]));
    t.cpu_seconds = ProcessCpuSeconds() - start;
    runs.push_back(std::move(t));
  }
  std::nth_element(runs.begin(), runs.begin() + runs.size() / 2, runs.end(),
                   [](const Timed& a, const Timed& b) { return a.cpu_seconds < b.cpu_seconds; });
  return std::move(runs[runs.size() / 2]);
}

std::string DefaultCacheDir() {
  const char* xdg = std::getenv("XDG_CACHE_HOME");
  if (xdg && xdg[0] == '/') return std::string(xdg) + "/raytracer/sweep";
  const char* home = std::getenv("HOME");
  return home && home[0] ? std::string(home) + "/.cache/raytracer/sweep" : std::string();
}

Reference ConvergedReference(const std::string& scene_path, rt::SceneDesc& scene, const Config& c,
                             int camera, rt::DevicePool& devices, const std::string& cache_dir) {
  const rt::CameraDesc& cam = scene.cameras[camera];
  struct stat st {};
  stat(scene_path.c_str(), &st);
  const int flags = c.path_flags >= 0 ? c.path_flags : cam.path_flags;
  char key[512];
  std::snprintf(
      key, sizeof key, "%s|%lld|%lld|cam %d|%dx%d|spp %d|seed %u|path %d|unbiased %d|%s%s",
      std::filesystem::absolute(scene_path).c_str(), static_cast<long long>(st.st_size),
      static_cast<long long>(st.st_mtime), camera, cam.width, cam.height, c.opt.spp, c.opt.seed,
      cam.path_tracing ? flags : -1, c.opt.unbiased_roulette ? 1 : 0,
      c.opt.precision == rt::Precision::kDouble ? "double" : "float", c.opt.mis ? "|mis" : "");
  char name[64];
  std::snprintf(name, sizeof name, "-%016zx.moments.exr", std::hash<std::string>()(key));
  const std::string path =
      cache_dir.empty()
          ? std::string()
          : cache_dir + "/" + std::filesystem::path(scene_path).stem().string() + name;
  Reference ref;
  std::error_code ec;
  if (!path.empty() && std::filesystem::exists(path, ec)) {
    ref.moments = rt::read_moments(path);
    ref.cached = true;
  } else {
    Timed t = Render(scene, c, camera, devices);
    ref.cpu_seconds = t.cpu_seconds;
    ref.moments =
        rt::moments_from_render(t.result, {c.opt.seed, t.result.spp, "box", c.device, key, camera});
    if (!path.empty()) {
      std::filesystem::create_directories(cache_dir, ec);
      rt::write_moments(path, ref.moments);
    }
  }
  ref.rgb = ref.moments.mean;
  return ref;
}

double TrimmedRelativeMse(const std::vector<float>& img, const std::vector<float>& ref,
                          double floor, double share) {
  std::vector<double> terms(ref.size());
  for (size_t i = 0; i < ref.size(); ++i) {
    const double d = static_cast<double>(img[i]) - ref[i];
    terms[i] = d * d / (static_cast<double>(ref[i]) * ref[i] + floor * floor);
  }
  const size_t keep = terms.size() - static_cast<size_t>(share * terms.size());
  if (keep == 0) return 0;
  std::nth_element(terms.begin(), terms.begin() + (keep - 1), terms.end());
  double sum = 0;
  for (size_t i = 0; i < keep; ++i) sum += terms[i];
  return sum / static_cast<double>(keep);
}

double MeanBias(const std::vector<float>& img, const std::vector<float>& ref) {
  double a = 0, b = 0;
  for (size_t i = 0; i < ref.size(); ++i) {
    a += img[i];
    b += ref[i];
  }
  return b > 0 ? a / b - 1.0 : 0.0;
}

double LoadAverage() {
  std::ifstream f("/proc/loadavg");
  double load = -1;
  f >> load;
  return f ? load : -1.0;
}

rt::SceneDesc LoadScaledScene(const std::string& path, int camera, double scale) {
  rt::SceneDesc scene = rt::load_scene(path);
  if (camera >= static_cast<int>(scene.cameras.size()))
    throw std::runtime_error(path + ": no camera " + std::to_string(camera));
  for (auto& cam : scene.cameras) {
    cam.width = std::max(1, static_cast<int>(std::lround(cam.width * scale)));
    cam.height = std::max(1, static_cast<int>(std::lround(cam.height * scale)));
  }
  return scene;
}

}  // namespace sweep
