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
                       DeviceLoadInfo* load_info) {
  Progress quiet(false, "", 0);
  if (test_precision_double() && !flat.double_precision) {
    FlatScene in_double = flat;
    in_double.double_precision = true;
    return render_camera(device, in_double, quiet, stop, nullptr, load_info);
  }
  return render_camera(device, flat, quiet, stop, nullptr, load_info);
}

RenderResult render_cpu(const FlatScene& flat, int threads, const StopRule& stop) {
  CpuDevice device(threads);
  return render_on(device, flat, stop);
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
