#include "device/cl/cl_program.h"

#include <algorithm>
#include <chrono>
#include <cinttypes>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <vector>

#include "app/progress.h"
#include "device/cl/cl_scene_buffers.h"
#include "io/file_util.h"

namespace rt {
namespace {

// FNV-1a, 64 bits; each part is prefixed with its length so concatenations differ.
class Fnv1a {
 public:
  void add(const void* data, size_t n) {
    const unsigned char* p = static_cast<const unsigned char*>(data);
    for (size_t i = 0; i < n; ++i) {
      h_ ^= p[i];
      h_ *= 0x100000001b3ull;
    }
  }
  void add(const std::string& s) {
    uint64_t n = s.size();
    add(&n, sizeof n);
    add(s.data(), s.size());
  }
  uint64_t value() const { return h_; }

 private:
  uint64_t h_ = 0xcbf29ce484222325ull;
};

std::filesystem::path cache_dir() {
  const char* xdg = std::getenv("XDG_CACHE_HOME");
  if (xdg && *xdg == '/') return std::filesystem::path(xdg) / "raytracer" / "kernels";
  const char* home = std::getenv("HOME");
  if (home && *home) return std::filesystem::path(home) / ".cache" / "raytracer" / "kernels";
  return {};
}

}  // namespace

ClProgramCache::ClProgramCache(const cl::Context& context, const cl::Device& device,
                               bool use_disk_cache)
    : context_(context), device_(device), queue_(context, device), use_disk_cache_(use_disk_cache) {
  cl::Platform platform(device_.getInfo<CL_DEVICE_PLATFORM>());
  platform_name_ = clean_cl_string(platform.getInfo<CL_PLATFORM_NAME>());
  name_ = clean_cl_string(device_.getInfo<CL_DEVICE_NAME>());
  device_version_ = clean_cl_string(device_.getInfo<CL_DEVICE_VERSION>());
  driver_version_ = clean_cl_string(device_.getInfo<CL_DRIVER_VERSION>());
  cl_device_fp_config fp = device_.getInfo<CL_DEVICE_SINGLE_FP_CONFIG>();
  correctly_rounded_ = (fp & CL_FP_CORRECTLY_ROUNDED_DIVIDE_SQRT) != 0;
  fp64_ = (" " + device_.getInfo<CL_DEVICE_EXTENSIONS>() + " ").find(" cl_khr_fp64 ") !=
          std::string::npos;
  cpu_ = (device_.getInfo<CL_DEVICE_TYPE>() & CL_DEVICE_TYPE_CPU) != 0;
}

void check_precision_support(const std::string& device_name, bool has_fp64, bool double_precision) {
  if (double_precision && !has_fp64)
    throw std::runtime_error("OpenCL device " + device_name +
                             " has no double precision (cl_khr_fp64): --precision double needs "
                             "it; use --precision float or --device cpu");
}

std::string ClProgramCache::options_for(int features, const KernelConfig& kernel) const {
  check_precision_support(name_, fp64_, kernel.double_precision);
  std::string o = kernel_defines(features, kernel);
  // Code whose best form differs between a CPU and a GPU asks which it runs on
  // (cl/integrator/pixel.h). RT_CL_GPU_FORMS=1, a developer's knob: a CPU device compiles the GPU
  // forms too (cl/compat.h), so that a machine without a GPU checks that they render the same
  // pixels.
  const char* gpu_forms = std::getenv("RT_CL_GPU_FORMS");
  if (cpu_ && !(gpu_forms && *gpu_forms && *gpu_forms != '0')) o += " -DRT_CL_CPU_DEVICE=1";
  if (correctly_rounded_) o += " -cl-fp32-correctly-rounded-divide-sqrt";
  // A developer's knob for experiments (e.g. RT_CL_OPTIONS=-cl-fast-relaxed-math).
  if (const char* extra = std::getenv("RT_CL_OPTIONS")) o += std::string(" ") + extra;
  if (kernel.fast_math) o += " -cl-fast-relaxed-math";
  return o;
}

cl::Program ClProgramCache::build(const std::string& source, const std::string& options,
                                  bool* hit) {
  *hit = false;
  std::vector<cl::Device> devices{device_};
  std::string file;
  if (use_disk_cache_ && !cache_dir().empty()) {
    Fnv1a h;
    for (const std::string& part :
         {source, options, platform_name_, name_, device_version_, driver_version_})
      h.add(part);
    char name[32];
    std::snprintf(name, sizeof name, "%016" PRIx64 ".bin", h.value());
    file = (cache_dir() / name).string();
    std::vector<uint8_t> binary;
    if (read_file(file, &binary) == 0 && !binary.empty()) {
      try {
        cl::Program::Binaries binaries{binary};
        cl::Program p(context_, devices, binaries);
        report_status("kernel from cache (" + name_ + ")");
        p.build(devices, options.c_str());
        *hit = true;
        return p;
      } catch (const cl::Error&) {
        // A stale or foreign binary: compile from source below and overwrite it.
      }
    }
  }
  // The compile takes seconds to a minute: the terminal says so rather than stay blank.
  report_status(std::string("compiling the OpenCL kernel for this scene's features") +
                (file.empty() ? "" : " (cached for later runs)") + "...");
  cl::Program p(context_, source);
  // PoCL's own kernel cache (~/.cache/pocl) is shared by every process; two processes that
  // compile the same kernel at once on a cold cache can race on its temporary files, and
  // the loser's build fails with "unable to rename temporary". That failure is transient,
  // so such a build is tried once more before it counts as an error.
  for (int attempt = 0;; ++attempt) {
    try {
      p.build(devices, options.c_str());
      break;
    } catch (const cl::Error& e) {
      std::string log;
      try {
        log = p.getBuildInfo<CL_PROGRAM_BUILD_LOG>(device_);
      } catch (const cl::Error&) {
        log = "(no build log available)";
      }
      if (attempt == 0 && log.find("unable to rename temporary") != std::string::npos) {
        p = cl::Program(context_, source);
        continue;
      }
      std::fprintf(stderr, "OpenCL build log for %s (options: %s):\n%s\n", name_.c_str(),
                   options.c_str(), clean_cl_string(log).c_str());
      std::fprintf(stderr, "OpenCL build error: %s\n", describe_cl_error(e).c_str());
      throw std::runtime_error("OpenCL: kernel build failed on " + name_ + " (see the log above)");
    }
  }
  if (!file.empty()) {
    // The cache is an optimisation only: any failure to store the binary is ignored.
    try {
      std::vector<std::vector<unsigned char>> bins = p.getInfo<CL_PROGRAM_BINARIES>();
      std::error_code ec;
      std::filesystem::create_directories(cache_dir(), ec);
      if (bins.size() == 1 && !bins[0].empty() && !ec)
        write_file_atomic(file, bins[0].data(), bins[0].size());
    } catch (const cl::Error&) {
    }
  }
  return p;
}

void ClProgramCache::print_build_report(const ClProgram& p, const std::string& options) const {
  // With -cl-nv-verbose (RT_CL_OPTIONS) NVIDIA's log holds ptxas's registers and spills.
  std::string log = clean_cl_string(p.program.getBuildInfo<CL_PROGRAM_BUILD_LOG>(device_));
  std::fprintf(stderr, "OpenCL build log for %s (options: %s):\n%s\n", name_.c_str(),
               options.c_str(), log.empty() ? "(empty)" : log.c_str());
  std::fprintf(
      stderr,
      "OpenCL kernel render on %s: private %llu B, local %llu B, work-group at most "
      "%zu\n",
      name_.c_str(),
      static_cast<unsigned long long>(
          p.kernel.getWorkGroupInfo<CL_KERNEL_PRIVATE_MEM_SIZE>(device_)),
      static_cast<unsigned long long>(p.kernel.getWorkGroupInfo<CL_KERNEL_LOCAL_MEM_SIZE>(device_)),
      static_cast<size_t>(p.kernel.getWorkGroupInfo<CL_KERNEL_WORK_GROUP_SIZE>(device_)));
}

ClProgram& ClProgramCache::get(const std::string& options, int bvh_width, double* compile_ms,
                               bool* cache_hit) {
  auto it = programs_.find(options);
  if (it != programs_.end()) {
    *compile_ms = 0;
    *cache_hit = true;  // Reused from memory.
    return it->second;
  }
  auto t0 = std::chrono::steady_clock::now();
  ClProgram p;
  p.program = build(kKernelSource, options, cache_hit);
  try {
    p.kernel = cl::Kernel(p.program, "render");
    size_t max_wg = p.kernel.getWorkGroupInfo<CL_KERNEL_WORK_GROUP_SIZE>(device_);
    std::vector<size_t> max_items = device_.getInfo<CL_DEVICE_MAX_WORK_ITEM_SIZES>();
    // 8x8 where the kernel allows it, else the largest power-of-two square-ish shape.
    while (p.local_x * p.local_y > max_wg) {
      if (p.local_y >= p.local_x && p.local_y > 1)
        p.local_y /= 2;
      else
        p.local_x /= 2;
    }
    if (max_items.size() >= 2) {
      p.local_x = std::max<size_t>(1, std::min(p.local_x, max_items[0]));
      p.local_y = std::max<size_t>(1, std::min(p.local_y, max_items[1]));
    }
    // Host and device must agree on every struct before anything is uploaded.
    check_scene_layout(context_, queue_, p.program, name_, bvh_width);
    if (const char* log = std::getenv("RT_CL_BUILD_LOG"); log && *log && *log != '0')
      print_build_report(p, options);
  } catch (const cl::Error& e) {
    throw std::runtime_error("OpenCL: " + describe_cl_error(e) + " on " + name_);
  }
  *compile_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  return programs_.emplace(options, std::move(p)).first->second;
}

}  // namespace rt
