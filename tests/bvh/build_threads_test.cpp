// The parallel BVH build (bvh_build.h) and the parallel parts of prepare_scene around it:
// the same tree, the same primitive order and the same scene bytes whatever the thread
// count, on inputs large enough for many parallel jobs, including the object-median
// fallback above the subtree threshold.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "bvh/bvh_build.h"
#include "prepare/flat_scene.h"
#include "support/geometry_harness.h"

namespace rt {
namespace {

// Terrain-like scattered boxes, then a cluster of identical ones: no split separates
// their centroids, so the build falls back to the object median on ranges larger than one
// subtree job.
std::vector<Aabb> MixedBoxes(int scattered, int identical) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> u(-100, 100), size(0, 2);
  std::vector<Aabb> boxes(scattered + identical);
  for (int i = 0; i < scattered; ++i) {
    float x = u(rng), y = u(rng), z = u(rng) * 0.01f;
    boxes[i].grow(x, y, z);
    boxes[i].grow(x + size(rng), y + size(rng), z + size(rng));
  }
  for (int i = scattered; i < scattered + identical; ++i)
    boxes[i].grow(500, 500, 500), boxes[i].grow(501, 501, 501);
  return boxes;
}

template <class T>
bool SameBytes(const T& a, const T& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(a[0])) == 0;
}

TEST(BvhBuildThreads, SameTreeForAnyThreadCount) {
  const std::vector<Aabb> boxes = MixedBoxes(150000, 40000);
  std::vector<BinaryBvhNode> first;
  std::vector<int> first_order;
  BvhBuildResult first_result;
  for (int threads : {1, 2, 3, 8}) {
    SCOPED_TRACE("threads " + std::to_string(threads));
    BvhOptions opt;
    opt.threads = threads;
    std::vector<BinaryBvhNode> nodes;
    std::vector<int> order;
    BvhBuildResult r = build_bvh(boxes, opt, 4, 7, nodes, order);
    if (threads == 1) {
      first = nodes, first_order = order, first_result = r;
      continue;
    }
    EXPECT_EQ(r.root, first_result.root);
    EXPECT_EQ(r.depth, first_result.depth);
    EXPECT_TRUE(SameBytes(nodes, first)) << "binary nodes differ";
    EXPECT_EQ(order, first_order);
  }
}

TEST(BvhBuildThreads, PrimitiveFormBuildsTheTreeOfTheBoxForm) {
  const std::vector<Aabb> boxes = MixedBoxes(30000, 100);
  std::vector<BinaryBvhNode> from_boxes, from_prims;
  std::vector<int> order;
  BvhOptions opt;
  opt.threads = 2;
  build_bvh(boxes, opt, 4, 0, from_boxes, order);
  std::vector<BvhPrimitive> prims(boxes.size());
  for (size_t i = 0; i < boxes.size(); ++i) {
    for (int k = 0; k < 3; ++k) prims[i].lo[k] = boxes[i].lo[k], prims[i].hi[k] = boxes[i].hi[k];
    prims[i].index = static_cast<int>(i);
    prims[i].unused = 0;
  }
  build_bvh(prims, opt, 4, 0, from_prims);
  EXPECT_TRUE(SameBytes(from_boxes, from_prims));
  for (size_t i = 0; i < prims.size(); ++i) ASSERT_EQ(prims[i].index, order[i]) << "position " << i;
}

// A smooth height field of 2 n^2 triangles, so that normals are copied too.
SceneDesc Terrain(int n) {
  SceneDesc s = test::BaseScene();
  std::vector<Vec3d> positions;
  std::vector<std::array<int, 3>> triangles;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      double x = -1 + 2.0 * i / n, y = -1 + 2.0 * j / n;
      positions.push_back({x, y, 0.05 * std::sin(23 * x) * std::cos(31 * y)});
    }
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      int a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
      triangles.push_back({a, b, d});
      triangles.push_back({a, d, c});
    }
  int mesh = test::AddMesh(s, positions, triangles);
  s.meshes[mesh].smooth = true;
  test::AddMeshObject(s, mesh, Mat4());
  return s;
}

TEST(BvhBuildThreads, FlattenedSceneIsTheSameBytesForOneAndTwoThreads) {
  const SceneDesc scene = Terrain(200);  // 80 000 triangles: several subtree jobs.
  RenderOptions opt;
  opt.bvh.threads = 1;
  const FlatScene one = prepare_scene(scene, opt);
  for (int threads : {2, 3}) {
    SCOPED_TRACE("threads " + std::to_string(threads));
    opt.bvh.threads = threads;
    const FlatScene many = prepare_scene(scene, opt);
    EXPECT_TRUE(SameBytes(one.nodes, many.nodes));
    EXPECT_TRUE(SameBytes(one.triangles, many.triangles));
    EXPECT_TRUE(SameBytes(one.normals, many.normals));
    EXPECT_TRUE(SameBytes(one.triangle_blocks, many.triangle_blocks));
    EXPECT_EQ(one.header.tlas_root, many.header.tlas_root);
  }
}

}  // namespace
}  // namespace rt
