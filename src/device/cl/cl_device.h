// The OpenCL device: runs cl/kernel.cl, compiled for the scene's features, on one OpenCL
// device, over the same flattened arrays as the CPU reference.
#pragma once

#include <memory>
#include <string>

#include "device/device.h"

namespace rt {

// Opens the device `options.cl_selector` names (see pick_cl_device). Returns nullptr and
// sets *why (one line) when no usable device exists.
std::unique_ptr<RenderDevice> create_cl_device(const DeviceOptions& options, std::string* why);

}  // namespace rt
