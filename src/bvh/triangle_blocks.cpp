#include "triangle_blocks.h"

#include "bvh_lanes.h"

#include <stdexcept>
#include <string>

namespace rt {

namespace {

// Blocks a leaf of `count` triangles takes.
int blocks_of(int count, int width) { return (count + width - 1) / width; }

bool is_leaf(int child) { return child <= -2; }

// One leaf's blocks: triangles [first, first + count) in lane order, the rest zero.
void append_blocks(const PageAlignedVector<Triangle>& triangles, int first, int count, int width,
                   PageAlignedVector<TriangleBlock>& blocks) {
  for (int b = 0; b < blocks_of(count, width); ++b) {
    WideBlock block(width);
    for (int lane = 0; lane < width; ++lane) {
      int i = b * width + lane;
      if (i >= count) break;
      const Triangle& tri = triangles[first + i];
      const float3* p[3] = {&tri.v0, &tri.v1, &tri.v2};
      for (int k = 0; k < 3; ++k) {
        block.set(3 * k, lane, p[k]->x);
        block.set(3 * k + 1, lane, p[k]->y);
        block.set(3 * k + 2, lane, p[k]->z);
      }
    }
    block.set_first(first + b * width);
    block.append_to(blocks);
  }
}

}  // namespace

void build_triangle_blocks(PageAlignedVector<BvhNode>& all_nodes, size_t blas_nodes, int width,
                           const PageAlignedVector<Triangle>& triangles,
                           PageAlignedVector<TriangleBlock>& blocks) {
  WideNodes nodes(all_nodes, width);
  const size_t blas_wide_nodes = blas_nodes / wide_units(width);
  // Counted first, so the array is allocated once at its final size.
  size_t total = 0;
  for (size_t n = 0; n < blas_wide_nodes; ++n)
    for (int lane = 0; lane < width; ++lane) {
      int child = nodes.child(n, lane);
      if (is_leaf(child)) total += blocks_of(RtLeafCount(child), width);
    }
  blocks.clear();
  blocks.reserve(total * wide_units(width));
  // Blocks follow the nodes' order (each mesh's nodes are depth first), so a subtree's
  // triangles lie close together in memory.
  for (size_t n = 0; n < blas_wide_nodes; ++n)
    for (int lane = 0; lane < width; ++lane) {
      int child = nodes.child(n, lane);
      if (!is_leaf(child)) continue;
      size_t first_block = blocks.size() / wide_units(width);
      if (first_block > static_cast<size_t>(RT_BVH_MAX_PRIMITIVES))
        throw std::length_error("BVH: " + std::to_string(total) +
                                " triangle blocks exceed the node format's limits");
      append_blocks(triangles, RtLeafFirst(child), RtLeafCount(child), width, blocks);
      nodes.set_child(n, lane, RtLeafRef(static_cast<int>(first_block), RtLeafCount(child)));
    }
}

}  // namespace rt
