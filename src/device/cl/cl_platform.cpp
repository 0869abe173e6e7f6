#include "device/cl/cl_platform.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>

namespace rt {
namespace {

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

std::string type_name(cl_device_type t) {
  if (t & CL_DEVICE_TYPE_GPU) return "GPU";
  if (t & CL_DEVICE_TYPE_CPU) return "CPU";
  if (t & CL_DEVICE_TYPE_ACCELERATOR) return "accelerator";
#ifdef CL_DEVICE_TYPE_CUSTOM
  if (t & CL_DEVICE_TYPE_CUSTOM) return "custom";
#endif
  return "other";
}

double mib(uint64_t bytes) { return static_cast<double>(bytes) / (1024.0 * 1024.0); }

// Every device of every platform, in the order --list-devices prints them. Throws
// cl::Error when the platform query itself fails; a platform without devices is skipped.
std::vector<ClDeviceEntry> enumerate_devices() {
  std::vector<cl::Platform> platforms;
  cl::Platform::get(&platforms);
  std::vector<ClDeviceEntry> out;
  for (const cl::Platform& p : platforms) {
    std::vector<cl::Device> devices;
    try {
      p.getDevices(CL_DEVICE_TYPE_ALL, &devices);
    } catch (const cl::Error&) {
      continue;  // CL_DEVICE_NOT_FOUND and friends: nothing usable on this platform.
    }
    for (const cl::Device& d : devices) out.push_back({p, d});
  }
  return out;
}

bool usable(const cl::Device& d) {
  try {
    return d.getInfo<CL_DEVICE_AVAILABLE>() && d.getInfo<CL_DEVICE_COMPILER_AVAILABLE>();
  } catch (const cl::Error&) {
    return false;
  }
}

// The entry `selector` names in `all`, or nullptr with *why set.
const ClDeviceEntry* select(const std::vector<ClDeviceEntry>& all, const std::string& selector,
                            std::string* why) {
  if (selector.empty()) {
    for (const auto& e : all)
      if ((e.device.getInfo<CL_DEVICE_TYPE>() & CL_DEVICE_TYPE_GPU) && usable(e.device)) return &e;
    for (const auto& e : all)
      if (usable(e.device)) return &e;
    return &all[0];  // Reported as unavailable by the caller.
  }
  if (std::all_of(selector.begin(), selector.end(),
                  [](char c) { return std::isdigit(static_cast<unsigned char>(c)); })) {
    unsigned long index = std::strtoul(selector.c_str(), nullptr, 10);
    if (selector.size() <= 9 && index < all.size()) return &all[index];
    *why = "no OpenCL device " + selector + " (there are " + std::to_string(all.size()) +
           "; see --list-devices)";
    return nullptr;
  }
  const std::string want = lower(selector);
  for (const auto& e : all)
    if (lower(clean_cl_string(e.device.getInfo<CL_DEVICE_NAME>())).find(want) != std::string::npos)
      return &e;
  *why = "no OpenCL device matches '" + selector + "' (see --list-devices)";
  return nullptr;
}

}  // namespace

bool pick_cl_device(const std::string& selector, ClDeviceEntry* pick, std::string* why) {
  try {
    std::vector<ClDeviceEntry> all;
    try {
      all = enumerate_devices();
    } catch (const cl::Error& e) {
      *why = "no OpenCL platform (" + describe_cl_error(e) + ")";
      return false;
    }
    if (all.empty()) {
      *why = "no OpenCL device found";
      return false;
    }
    const ClDeviceEntry* e = select(all, selector, why);
    if (!e) return false;
    const std::string name = clean_cl_string(e->device.getInfo<CL_DEVICE_NAME>());
    if (!e->device.getInfo<CL_DEVICE_AVAILABLE>()) {
      *why = "OpenCL device " + name + " is not available";
      return false;
    }
    if (!e->device.getInfo<CL_DEVICE_COMPILER_AVAILABLE>()) {
      *why = "OpenCL device " + name + " has no compiler";
      return false;
    }
    *pick = *e;
    return true;
  } catch (const cl::Error& e) {
    *why = describe_cl_error(e);
  }
  return false;
}

bool list_cl_devices(std::FILE* out) {
  std::vector<ClDeviceEntry> all;
  try {
    all = enumerate_devices();
  } catch (const cl::Error& e) {
    std::fprintf(out, "no OpenCL platform found (%s)\n", describe_cl_error(e).c_str());
    return false;
  }
  if (all.empty()) {
    std::fprintf(out, "no OpenCL device found\n");
    return false;
  }
  for (size_t i = 0; i < all.size(); ++i) {
    try {
      const cl::Device& d = all[i].device;
      std::fprintf(out, "%zu: %s (platform %s, %s, %u compute units, %.0f MiB global memory, %s)\n",
                   i, clean_cl_string(d.getInfo<CL_DEVICE_NAME>()).c_str(),
                   clean_cl_string(all[i].platform.getInfo<CL_PLATFORM_NAME>()).c_str(),
                   type_name(d.getInfo<CL_DEVICE_TYPE>()).c_str(),
                   static_cast<unsigned>(d.getInfo<CL_DEVICE_MAX_COMPUTE_UNITS>()),
                   mib(d.getInfo<CL_DEVICE_GLOBAL_MEM_SIZE>()),
                   clean_cl_string(d.getInfo<CL_DEVICE_OPENCL_C_VERSION>()).c_str());
    } catch (const cl::Error& e) {
      std::fprintf(out, "%zu: (cannot query the device: %s)\n", i, describe_cl_error(e).c_str());
    }
  }
  return true;
}

}  // namespace rt
