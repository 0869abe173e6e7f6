// Binned-SAH construction of a binary BVH on the host; src/bvh/bvh_wide.h collapses it into
// the wide nodes the devices traverse (cl/scene_types.h).
#pragma once

#include <vector>

#include "cl/scene_types.h"

namespace rt {

struct Aabb {
  float lo[3] = {3.4e38f, 3.4e38f, 3.4e38f};
  float hi[3] = {-3.4e38f, -3.4e38f, -3.4e38f};

  void grow(const Aabb& b);
  void grow(float x, float y, float z);
  float area() const;
  bool empty() const { return lo[0] > hi[0]; }
};

// Build-quality settings (the speed/accuracy trade measures them).
struct BvhOptions {
  int bins = 16;     // SAH bins per axis.
  int max_leaf = 4;  // Primitives per leaf the SAH may stop at (the top level uses 1).
  int threads = 0;   // Build threads; 0: all cores. The tree does not depend on it.
  // Children per wide node (and triangles per leaf block): 4 or 8; 0 takes this build's
  // RT_BVH_WIDTH, the one the CPU reference is compiled for. The executable asks the device
  // (RenderDevice::bvh_width). The binary tree, and so the image, do not depend on it.
  int width = 0;
};

// The children per wide node `options` build: its width, or RT_BVH_WIDTH for 0.
inline int node_width(const BvhOptions& options) {
  return options.width != 0 ? options.width : RT_BVH_WIDTH;
}

// A binary node: leaf when count > 0 (primitives first..first+count-1), otherwise an
// interior node whose children are first and first+1, split along axis -count.
struct BinaryBvhNode {
  float lo[3];
  int first;
  float hi[3];
  int count;
};

// A primitive as the builder sees it: its box and its index, 32 bytes, moved as a whole
// when the builder partitions (so every pass reads memory in order). The caller fills
// `lo`, `hi` and `index`; the build leaves them in leaf order.
struct alignas(16) BvhPrimitive {
  BvhPrimitive() {}  // Left unset: arrays of millions are filled in parallel, not zeroed first.
  float lo[3];
  int index;
  float hi[3];
  int unused;
};

struct BvhBuildResult {
  int root = -1;
  int depth = 0;
};

// Builds a BVH over `prims` into `nodes`, reordering `prims`: leaves refer to positions
// first..first+count-1 of it, shifted by `prim_offset`; the caller stores its primitives in
// that order (prims[i].index). The tree and the order do not depend on options.threads.
BvhBuildResult build_bvh(std::vector<BvhPrimitive>& prims, const BvhOptions& options, int max_leaf,
                         int prim_offset, std::vector<BinaryBvhNode>& nodes);

// The same over `boxes`, primitive i having box i; `order` receives the primitives' order.
BvhBuildResult build_bvh(const std::vector<Aabb>& boxes, const BvhOptions& options, int max_leaf,
                         int prim_offset, std::vector<BinaryBvhNode>& nodes,
                         std::vector<int>& order);

}  // namespace rt
