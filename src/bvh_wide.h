// Collapses a binary BVH (src/bvh_build.h) into the wide nodes both devices traverse
// (cl/scene_types.h), RT_BVH_WIDTH children per node.
#pragma once

#include <vector>

#include "bvh_build.h"
#include "util/page_aligned.h"

namespace rt {

struct WideBvhResult {
  int root = -1;  // Index of the root node in the wide array; -1 for an empty tree.
  int depth = 0;  // Wide levels below the root.
};

// Appends the wide form of the binary tree rooted at `root` to `wide`. The root is always
// an interior wide node, even when the binary tree is a single leaf, so traversal starts
// with a node test. Leaves keep their primitive ranges, at most RT_BVH_MAX_LEAF each.
WideBvhResult collapse_bvh(const std::vector<BinaryBvhNode>& binary, int root,
                           PageAlignedVector<BvhNode>& wide);

}  // namespace rt
