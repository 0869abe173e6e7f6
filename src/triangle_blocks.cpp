#include "triangle_blocks.h"

#include "bvh_lanes.h"

#include <cstring>
#include <stdexcept>
#include <string>

namespace rt {

namespace {

// Blocks a leaf of `count` triangles takes.
int blocks_of(int count) { return (count + RT_BVH_WIDTH - 1) / RT_BVH_WIDTH; }

bool is_leaf(int child) { return child <= -2; }

// One leaf's blocks: triangles [first, first + count) in lane order, the rest zero.
void append_blocks(const PageAlignedVector<Triangle>& triangles, int first, int count,
                   PageAlignedVector<TriangleBlock>& blocks) {
  for (int b = 0; b < blocks_of(count); ++b) {
    float v[9][RT_BVH_WIDTH] = {};
    for (int lane = 0; lane < RT_BVH_WIDTH; ++lane) {
      int i = b * RT_BVH_WIDTH + lane;
      if (i >= count) break;
      const Triangle& tri = triangles[first + i];
      const float3* p[3] = {&tri.v0, &tri.v1, &tri.v2};
      for (int k = 0; k < 3; ++k) {
        v[3 * k][lane] = p[k]->x;
        v[3 * k + 1][lane] = p[k]->y;
        v[3 * k + 2][lane] = p[k]->z;
      }
    }
    TriangleBlock block;
    std::memset(&block, 0, sizeof block);
    for (int j = 0; j < 9; ++j) std::memcpy(&block.v[j], v[j], sizeof block.v[j]);
    block.first = first + b * RT_BVH_WIDTH;
    blocks.push_back(block);
  }
}

}  // namespace

void build_triangle_blocks(FlatScene& f) {
  // Counted first, so the array is allocated once at its final size.
  size_t total = 0;
  for (size_t n = 0; n < f.blas_nodes; ++n)
    for (int lane = 0; lane < RT_BVH_WIDTH; ++lane) {
      int child = lane_of(f.nodes[n].child, lane);
      if (is_leaf(child)) total += blocks_of(RtLeafCount(child));
    }
  f.triangle_blocks.clear();
  f.triangle_blocks.reserve(total);
  // Blocks follow the nodes' order (each mesh's nodes are depth first), so a subtree's
  // triangles lie close together in memory.
  for (size_t n = 0; n < f.blas_nodes; ++n)
    for (int lane = 0; lane < RT_BVH_WIDTH; ++lane) {
      int child = lane_of(f.nodes[n].child, lane);
      if (!is_leaf(child)) continue;
      size_t first_block = f.triangle_blocks.size();
      if (first_block > static_cast<size_t>(RT_BVH_MAX_PRIMITIVES))
        throw std::length_error("BVH: " + std::to_string(total) +
                                " triangle blocks exceed the node format's limits");
      append_blocks(f.triangles, RtLeafFirst(child), RtLeafCount(child), f.triangle_blocks);
      set_lane(f.nodes[n].child, lane,
               RtLeafRef(static_cast<int>(first_block), RtLeafCount(child)));
    }
}

}  // namespace rt
