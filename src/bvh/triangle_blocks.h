// The bottom-level leaves as blocks of FlatScene::bvh_width triangles (TriangleBlock,
// cl/scene_types.h), structure of arrays, which the traversal tests a block at a time.
#pragma once

#include "prepare/flat_scene.h"

namespace rt {

// Makes f.triangle_blocks from f.triangles and rewrites every leaf reference of the bottom
// levels (the nodes in f.nodes[0, f.blas_nodes)) from its first triangle to its first block; the
// triangle count stays. Called once, after every mesh's BVH and triangles are in place.
void build_triangle_blocks(FlatScene& f);

}  // namespace rt
