#include "device/device.h"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <stdexcept>

#include "device/cl/cl_device.h"
#include "device/cpu/cpu_device.h"

namespace rt {

void RenderDevice::write_film(const std::vector<PixelAccum>&, const std::vector<PrimaryInfo>&) {
  throw std::runtime_error(name() + ": cannot load a saved film");
}

std::string format_bytes(uint64_t bytes) {
  const char* units[] = {"bytes", "KiB", "MiB", "GiB", "TiB", "PiB"};
  double v = static_cast<double>(bytes);
  int u = 0;
  while (v >= 1024 && u < 5) {
    v /= 1024;
    ++u;
  }
  char text[64];
  if (u == 0)
    std::snprintf(text, sizeof text, "%llu bytes", static_cast<unsigned long long>(bytes));
  else
    std::snprintf(text, sizeof text, "%.1f %s (%llu bytes)", v, units[u],
                  static_cast<unsigned long long>(bytes));
  return text;
}

int resolve_bvh_width(int asked, const RenderDevice& device) {
  if (asked == 0) return device.bvh_width();
  if (!device.supports_bvh_width(asked))
    throw std::runtime_error("--bvh-width " + std::to_string(asked) + ": " + device.name() +
                             " renders " + std::to_string(device.bvh_width()) +
                             "-wide BVH nodes only");
  return asked;
}

KernelConfig kernel_config(const RenderOptions& options) {
  if (options.precision == Precision::kAuto)
    throw std::logic_error("--precision auto reached the kernel unresolved (resolve_precision)");
  KernelConfig k;
  k.fast_math = options.fast_math;
  k.double_precision = options.precision == Precision::kDouble;
  k.bvh_width = node_width(options.bvh);
  return k;
}

PreparedScene prepare_for_device(const SceneDesc& scene, const RenderOptions& options,
                                 const RenderDevice& device, std::string* notice) {
  PreparedScene p;
  p.options = options;
  p.options.precision =
      resolve_precision(options.precision, device.has_double(), device.name(), notice);
  p.options.bvh.width = resolve_bvh_width(options.bvh.width, device);
  p.kernel = kernel_config(p.options);
  p.flat = prepare_scene(scene, p.options);
  return p;
}

void prepare_camera(PreparedScene& prepared, const SceneDesc& scene, int camera) {
  prepare_camera(prepared.flat, scene, camera, prepared.options);
}

MemoryNeed camera_memory_need(const PreparedScene& prepared, const SceneDesc& scene, int camera,
                              uint64_t host_bytes) {
  MemoryNeed need;
  need.arrays = camera_array_counts(prepared.flat, scene, prepared.options);
  need.width = scene.cameras[camera].width;
  need.height = scene.cameras[camera].height;
  need.host_bytes = host_bytes;
  return need;
}

void check_memory_limit(const MemoryNeed& need, uint64_t bytes, uint64_t limit,
                        const std::string& what, const std::string& limit_text) {
  if (bytes <= limit) return;
  throw std::runtime_error(std::to_string(need.width) + "x" + std::to_string(need.height) +
                           " pixels need " + format_bytes(bytes) + " of " + what + ", more than " +
                           limit_text);
}

uint64_t available_host_memory() {
  uint64_t available = 0;
  std::ifstream meminfo("/proc/meminfo");
  std::string key;
  uint64_t kib = 0;
  while (meminfo >> key >> kib) {
    if (key == "MemAvailable:") {
      available = kib * 1024;
      break;
    }
    meminfo.ignore(256, '\n');
  }
  if (available == 0) {
    const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGESIZE);
    if (pages > 0 && page > 0) available = static_cast<uint64_t>(pages) * page;
  }
  for (int resource : {RLIMIT_AS, RLIMIT_DATA}) {
    struct rlimit rl;
    if (getrlimit(resource, &rl) == 0 && rl.rlim_cur != RLIM_INFINITY)
      available = std::min<uint64_t>(available ? available : UINT64_MAX, rl.rlim_cur);
  }
  return available ? available : UINT64_MAX;
}

std::unique_ptr<RenderDevice> create_device(const DeviceOptions& options, std::string* notice) {
  notice->clear();
  if (options.kind == Device::kCpu) return std::make_unique<CpuDevice>(options.threads);
  std::string why;
  if (std::unique_ptr<RenderDevice> cl = create_cl_device(options, &why)) return cl;
  if (options.kind == Device::kOpenCl) throw std::runtime_error("OpenCL: " + why);
  *notice = "no usable OpenCL device (" + why + "); using the CPU reference";
  return std::make_unique<CpuDevice>(options.threads);
}

RenderDevice* DevicePool::get(const DeviceOptions& options, std::string* why) {
  const std::string key = std::to_string(static_cast<int>(options.kind)) + "|" +
                          options.cl_selector + "|" + std::to_string(options.kernel_cache) +
                          std::to_string(options.generic_kernel) + "|" +
                          std::to_string(options.threads) + "|" + std::to_string(options.gpu_rank);
  auto it = devices_.find(key);
  if (it == devices_.end()) {
    Entry e;
    try {
      std::string notice;
      e.device = create_device(options, &notice);
    } catch (const std::exception& ex) {
      e.why = ex.what();
    }
    it = devices_.emplace(key, std::move(e)).first;
  }
  if (why) *why = it->second.why;
  return it->second.device.get();
}

}  // namespace rt
