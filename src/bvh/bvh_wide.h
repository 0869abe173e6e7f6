// Collapses a binary BVH (src/bvh/bvh_build.h) into the wide nodes both devices traverse
// (cl/scene_types.h), up to `width` children per node (src/bvh/bvh_lanes.h).
#pragma once

#include <vector>

#include "bvh_build.h"
#include "bvh_lanes.h"

namespace rt {

struct WideBvhResult {
  int root = -1;  // Index of the root node in the wide array; -1 for an empty tree.
  int depth = 0;  // Wide levels below the root.
};

// Appends the wide form of the binary tree rooted at `root` to `wide`. The root is always
// an interior wide node, even when the binary tree is a single leaf, so traversal starts
// with a node test. Leaves keep their primitive ranges, at most RT_BVH_MAX_LEAF each; with
// `merge_leaves` (triangle levels, whose leaves are tested a block of `width` at a time),
// neighbouring leaves of one node that fit one block together become one leaf, so that
// 8-wide blocks of a tree built with leaves of 4 are not left half empty. The order of
// the primitives, and so every hit, stays the binary tree's.
WideBvhResult collapse_bvh(const std::vector<BinaryBvhNode>& binary, int root, WideNodes wide,
                           bool merge_leaves = false);

}  // namespace rt
