#include "support/device_harness.h"

#include "device/cpu_device.h"

namespace rt::test {

RenderDevice* shared_device(Device kind, std::string* why, bool generic_kernel, bool kernel_cache) {
  static DevicePool pool;
  DeviceOptions options;
  options.kind = kind;
  options.generic_kernel = generic_kernel;
  options.kernel_cache = kernel_cache;
  return pool.get(options, why);
}

RenderResult render_on(RenderDevice& device, const FlatScene& flat, const StopRule& stop,
                       DeviceLoadInfo* load_info) {
  Progress quiet(false, "", 0);
  return render_camera(device, flat, quiet, stop, nullptr, load_info);
}

RenderResult render_cpu(const FlatScene& flat, int threads, const StopRule& stop) {
  CpuDevice device(threads);
  return render_on(device, flat, stop);
}

const char* device_label(Device kind) { return kind == Device::kCpu ? "cpu" : "cl"; }

}  // namespace rt::test
