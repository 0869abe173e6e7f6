// How a device builds (OpenCL) or selects (CPU reference) the kernel for a prepared scene:
// the settings that are not the scene's data, and the sizes of the kernel's private arrays
// that the placed scene bounds.
#pragma once

#include <string>

#include "cl/scene_types.h"

namespace rt {

struct FlatScene;

struct KernelConfig {
  bool fast_math = false;         // OpenCL: -cl-fast-relaxed-math (the CPU stays precise).
  bool double_precision = false;  // The build of the shared math that runs (cl/util/real.h).
  // Children per BVH node and triangles per block of the scene's arrays (src/bvh/bvh_lanes.h):
  // the kernel must be built for the width the arrays were prepared with.
  int bvh_width = RT_BVH_WIDTH;
  // The OpenCL kernel's BVH stack entries (-DRT_BVH_STACK) and deepest ray tree
  // (-DRT_RAY_TREE_DEPTH), set by sized_for_scene; 0 and -1 leave the kernel's static
  // bounds (cl/bvh/bvh.h, cl/integrator/ray_tree.h), which the CPU reference always uses.
  int bvh_stack = 0;
  int ray_tree_depth = -1;
};

// The entries of BVH stack that bucket `needed` (RT_BVH_STACK_NEEDED) takes: a multiple of
// 16, at least 32, so that scenes of similar depths share one compiled kernel.
int bvh_stack_bucket(int needed);

// `kernel` with the private arrays sized for the scene placed in `flat` (prepare_camera):
// the BVH stack from its trees' depths, the ray tree from its MaxRecursionDepth. Throws
// std::runtime_error when the trees need more stack than the kernel's static bound
// (RT_BVH_STACK_MAX), which the CPU reference traverses with.
KernelConfig sized_for_scene(const KernelConfig& kernel, const FlatScene& flat);

// The build options of the kernel for `features` that any OpenCL device gets: the language
// version, the feature set, node width, stack and ray-tree sizes and precision. A device
// adds its own (ClProgramCache::options_for).
std::string kernel_defines(int features, const KernelConfig& kernel);

}  // namespace rt
