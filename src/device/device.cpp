#include "device/device.h"

#include <stdexcept>

#include "device/cl/cl_device.h"
#include "device/cpu_device.h"

namespace rt {

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
                          std::to_string(options.threads);
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
