// OpenCL device discovery: every device of every platform, in one order (the indices
// --list-devices prints and --cl-device accepts), and the choice of one by selector.
#pragma once

#include <cstdio>
#include <string>
#include <vector>

#include "device/cl/opencl.h"

namespace rt {

struct ClDeviceEntry {
  cl::Platform platform;
  cl::Device device;
};

// Picks a usable device: `selector` is an index into the list list_cl_devices prints, or a
// case-insensitive substring of a device name; empty picks the first GPU, else the first
// device. Returns false and sets *why (one line) when there is none.
bool pick_cl_device(const std::string& selector, ClDeviceEntry* pick, std::string* why);

// Prints every platform and device with its index; false when there is none.
bool list_cl_devices(std::FILE* out);

}  // namespace rt
