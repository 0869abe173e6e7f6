#include "device/kernel_config.h"

#include <stdexcept>

#include "cl/bvh/bvh.h"
#include "prepare/flat_scene.h"

namespace rt {

int bvh_stack_bucket(int needed) {
  // Not below 32: AMD's compiler keeps a stack of 16 entries in registers, which it then
  // lacks for the rest of the kernel (gfx90a: hw4 wood_box_all at 289 VGPRs with spills,
  // against 248 with 32 entries in scratch).
  return needed <= 32 ? 32 : (needed + 15) / 16 * 16;
}

KernelConfig sized_for_scene(const KernelConfig& kernel, const FlatScene& flat) {
  KernelConfig k = kernel;
  // FlatStats' depths count the levels below the root.
  const int needed =
      RT_BVH_STACK_NEEDED(k.bvh_width, flat.stats.tlas_depth + 1, flat.stats.max_blas_depth + 1);
  const int limit = RT_BVH_STACK_MAX(k.bvh_width);
  if (needed > limit)
    throw std::runtime_error("BVH too deep: a top level of depth " +
                             std::to_string(flat.stats.tlas_depth) + " over meshes of depth " +
                             std::to_string(flat.stats.max_blas_depth) + " needs " +
                             std::to_string(needed) + " stack entries, more than the " +
                             std::to_string(limit) + " the traversal has");
  k.bvh_stack = bvh_stack_bucket(needed);
  if (k.bvh_stack > limit) k.bvh_stack = limit;
  const int depth = flat.header.max_depth;
  k.ray_tree_depth = depth < 0 ? 0 : depth > RT_MAX_DEPTH ? RT_MAX_DEPTH : depth;
  return k;
}

std::string kernel_defines(int features, const KernelConfig& kernel) {
  std::string o = "-cl-std=CL1.2 -DRT_KERNEL_FEATURES=" + std::to_string(features);
  // The width of the nodes and triangle blocks the host built (cl/bvh/simd.h, src/bvh/bvh_lanes.h).
  o += " -DRT_BVH_WIDTH=" + std::to_string(kernel.bvh_width);
  if (kernel.bvh_stack > 0) o += " -DRT_BVH_STACK=" + std::to_string(kernel.bvh_stack);
  if (kernel.ray_tree_depth >= 0)
    o += " -DRT_RAY_TREE_DEPTH=" + std::to_string(kernel.ray_tree_depth);
  if (kernel.double_precision) o += " -DRT_REAL_DOUBLE=1";
  return o;
}

}  // namespace rt
