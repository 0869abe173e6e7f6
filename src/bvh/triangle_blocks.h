// The bottom-level leaves as blocks of `width` triangles (TriangleBlock,
// cl/scene_types.h), structure of arrays, which the traversal tests a block at a time.
#pragma once

#include <cstddef>

#include "cl/scene_types.h"
#include "util/page_aligned.h"

namespace rt {

// Makes `blocks` from `triangles` and rewrites every leaf reference of the bottom levels
// (nodes[0, blas_nodes) of nodes `width` wide) from its first triangle to its first block;
// the triangle count stays. Called once, after every mesh's BVH and triangles are in place.
void build_triangle_blocks(PageAlignedVector<BvhNode>& nodes, size_t blas_nodes, int width,
                           const PageAlignedVector<Triangle>& triangles,
                           PageAlignedVector<TriangleBlock>& blocks);

}  // namespace rt
