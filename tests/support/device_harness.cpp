#include "support/device_harness.h"

#include <cstdlib>
#include <cstring>

#include "device/cpu/cpu_device.h"

namespace rt::test {

RenderDevice* shared_device(Device kind, std::string* why, bool generic_kernel, bool kernel_cache) {
  static DevicePool pool;
  DeviceOptions options;
  options.kind = kind;
  options.generic_kernel = generic_kernel;
  options.kernel_cache = kernel_cache;
  return pool.get(options, why);
}

bool test_precision_double() {
  const char* p = std::getenv("RT_TEST_PRECISION");
  return p && std::strcmp(p, "double") == 0;
}

RenderResult render_on(RenderDevice& device, const FlatScene& flat, const StopRule& stop,
                       DeviceLoadInfo* load_info, const KernelConfig& kernel) {
  Progress quiet(false, "", 0);
  KernelConfig config = kernel;
  config.double_precision = config.double_precision || test_precision_double();
  return render_camera(device, flat, config, quiet, stop, nullptr, load_info);
}

RenderResult render_cpu(const FlatScene& flat, int threads, const StopRule& stop,
                        const KernelConfig& kernel) {
  CpuDevice device(threads);
  return render_on(device, flat, stop, nullptr, kernel);
}

PreparedScene prepare_on(const RenderDevice& device, const SceneDesc& scene, int camera,
                         const RenderOptions& options) {
  std::string notice;
  PreparedScene prepared = prepare_for_device(scene, options, device, &notice);
  prepare_camera(prepared, scene, camera);
  return prepared;
}

const char* device_label(Device kind) { return kind == Device::kCpu ? "cpu" : "cl"; }

int common_sample_count(const RenderResult& r) {
  if (r.accum.empty()) return -1;
  const int n = static_cast<int>(r.accum[0].sum_sq.w);
  for (const PixelAccum& a : r.accum)
    if (static_cast<int>(a.sum_sq.w) != n) return -1;
  return n;
}

}  // namespace rt::test
