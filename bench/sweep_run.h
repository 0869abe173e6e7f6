// One configuration of the speed-accuracy sweep (bench/sweep.cpp), rendered and timed in
// CPU-seconds, and the converged references its error is measured against, rendered once
// and cached as moment files.
#pragma once

#include <string>
#include <vector>

#include "device/device.h"
#include "integrator/render.h"
#include "io/moments.h"
#include "scene/scene.h"

namespace sweep {

struct Config {
  std::string axis, name, device;  // device: "cpu" or "cl"
  rt::RenderOptions opt;
  bool generic = false;
  // Path-traced cameras: the RT_FLAG_NEXT_EVENT / IMPORTANCE_SAMPLING / RUSSIAN_ROULETTE
  // options to render with instead of the camera's <RendererParams>; -1: the camera's.
  int path_flags = -1;
};

struct Timed {
  rt::RenderResult result;
  double cpu_seconds = 0;  // User + system time of the whole process during the render.
  double build_ms = 0;     // The BVH build (not in the render's time).
};

// Renders camera `camera` of `scene` with configuration `c`. The program is built and the
// scene loaded once before the clock starts, so compile time is not counted; the process's
// CPU time covers the CPU reference's threads and PoCL's alike. `reps` > 1 renders again
// and keeps the run of median CPU time. Throws std::runtime_error when the device is
// missing.
Timed Render(rt::SceneDesc& scene, const Config& c, int camera, rt::DevicePool& devices,
             int reps = 1);

// A converged reference: the moment file of `c` rendered at c.opt.spp, read from
// `cache_dir` when an earlier run left it there (keyed by the scene file, its size and
// modification time, the camera, its resolution and every option that changes the
// expectation), else rendered on the CPU and written there. An empty cache_dir: no cache.
struct Reference {
  rt::MomentImage moments;
  std::vector<float> rgb;  // moments.mean, the image.
  double cpu_seconds = 0;  // Of the render; 0 when read from the cache.
  bool cached = false;
};
Reference ConvergedReference(const std::string& scene_path, rt::SceneDesc& scene, const Config& c,
                             int camera, rt::DevicePool& devices, const std::string& cache_dir);

// The default cache: $XDG_CACHE_HOME/raytracer/sweep, else $HOME/.cache/raytracer/sweep.
std::string DefaultCacheDir();

// The scene file at `path` with every camera's resolution scaled by `scale` (rounded, at
// least 1 pixel); throws when it has no camera `camera`.
rt::SceneDesc LoadScaledScene(const std::string& path, int camera, double scale);

// rt::relative_mse without the largest `share` of its per-value terms. A path tracer's
// error is heavy-tailed (a vertex near the point light, a rare caustic): over 64x64 pixels
// a dozen values can outweigh the rest, and the plain mean then moves up and down with
// the sample count; dropping the largest 0.1 % (as rendering papers often report it)
// shows the trend the rest of the image follows.
double TrimmedRelativeMse(const std::vector<float>& img, const std::vector<float>& ref,
                          double floor, double share);

// Mean over pixels and channels of img / mean of ref, minus 1: the image's overall bias.
double MeanBias(const std::vector<float>& img, const std::vector<float>& ref);

// The load average over the last minute, from /proc/loadavg (-1 when unreadable).
double LoadAverage();

}  // namespace sweep
