// How a device builds (OpenCL) or selects (CPU reference) the kernel for a prepared scene:
// the settings that are not the scene's data.
#pragma once

#include "cl/scene_types.h"

namespace rt {

struct KernelConfig {
  bool fast_math = false;         // OpenCL: -cl-fast-relaxed-math (the CPU stays precise).
  bool double_precision = false;  // The build of the shared math that runs (cl/util/real.h).
  // Children per BVH node and triangles per block of the scene's arrays (src/bvh/bvh_lanes.h):
  // the kernel must be built for the width the arrays were prepared with.
  int bvh_width = RT_BVH_WIDTH;
};

}  // namespace rt
