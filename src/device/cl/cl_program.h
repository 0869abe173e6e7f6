// Building the render program for one OpenCL device: build options, an on-disk cache of
// compiled binaries, the check that host and device agree on every struct layout
// (check_scene_layout of cl_scene_buffers.h), and the
// work-group shape. Programs are kept in memory by build options, so cameras and renders
// that need the same features build once.
#pragma once

#include <map>
#include <string>

#include "device/cl/opencl.h"
#include "device/kernel_config.h"

namespace rt {

struct ClProgram {
  cl::Program program;
  cl::Kernel kernel;  // `render` of cl/kernel.cl.
  size_t local_x = 8, local_y = 8;
  bool warmed = false;  // The first launch (and any lazy device compile) has happened.
};

class ClProgramCache {
 public:
  ClProgramCache(const cl::Context& context, const cl::Device& device, bool use_disk_cache);
  // The build options for a feature set: kernel_defines (the scene's node width, BVH stack
  // and ray-tree depth among them), exact division and square root when the device offers them,
  // RT_CL_CPU_DEVICE on a CPU device, the kernel configuration's fast math, node width and
  // RT_REAL_DOUBLE for double precision (which throws, naming the device, when it lacks
  // cl_khr_fp64), and RT_CL_OPTIONS (a developer's knob). The options key both the in-memory and
  // the on-disk cache.
  std::string options_for(int features, const KernelConfig& kernel) const;
  // The program built with `options`, whose node width is `bvh_width`. *compile_ms is the
  // time it took (0 when it was in memory), *cache_hit whether it came from memory or the
  // disk cache. Throws std::runtime_error (one line; the build log goes to stderr in full).
  ClProgram& get(const std::string& options, int bvh_width, double* compile_ms, bool* cache_hit);
  bool has_double() const { return fp64_; }
  bool is_cpu() const { return cpu_; }

 private:
  // RT_CL_BUILD_LOG set (not 0): the build log of a built program and its render kernel's
  // private and local memory and largest work-group, on stderr.
  void print_build_report(const ClProgram& p, const std::string& options) const;
  cl::Program build(const std::string& source, const std::string& options, bool* hit);

  cl::Context context_;
  cl::Device device_;
  cl::CommandQueue queue_;
  std::string platform_name_, name_, device_version_, driver_version_;
  bool use_disk_cache_;
  bool correctly_rounded_ = false;
  bool fp64_ = false;  // The device reports cl_khr_fp64.
  bool cpu_ = false;   // The device is a CPU (PoCL's pthread device, say).
  std::map<std::string, ClProgram> programs_;
};

// Throws std::runtime_error (one line naming the device) when `double_precision` is asked
// of a device without cl_khr_fp64.
void check_precision_support(const std::string& device_name, bool has_fp64, bool double_precision);

// The kernel source with every shared header inlined (generated at build time).
extern const char* const kKernelSource;

}  // namespace rt
