// The arithmetic of the shared math (cl/util/real.h): what --precision asks for, and how
// `auto` becomes float or double once the device is known.
#pragma once

#include <string>

namespace rt {

enum class Precision { kFloat, kDouble, kAuto };

// --precision auto: double where the device computes it (the CPU reference always, an
// OpenCL device when it reports cl_khr_fp64), else float with *notice set to one line
// naming the device. float and double pass through (a device without fp64 refuses double
// when its program is built). *notice is empty unless auto fell back.
Precision resolve_precision(Precision asked, bool device_has_fp64, const std::string& device_name,
                            std::string* notice);

}  // namespace rt
