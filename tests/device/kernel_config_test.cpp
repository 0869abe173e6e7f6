// The kernel's private arrays sized from the scene (src/device/kernel_config.cpp): the BVH
// stack bound of cl/bvh/bvh.h against the worst a traversal of the flattened trees can push,
// its buckets and refusal, the ray tree's depth, and the build options that carry them.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "device/kernel_config.h"
#include "support/geometry_harness.h"

namespace rt {
namespace {

using namespace test;

// The most entries a traversal of `f` can hold, walked over the arrays themselves rather
// than the depths: a node pushes every hit child but the one it visits (all its non-empty
// lanes hit, at worst, any of them visited first), and entering a mesh pushes a sentinel.
int WorstStack(const FlatScene& f, int node, bool top) {
  const BvhNode& n = f.nodes[node];
  int children = 0, deepest = 0;
  for (int i = 0; i < RT_BVH_WIDTH; ++i) {
    const int ref = n.child[i];
    if (ref == RT_BVH_EMPTY) continue;
    ++children;
    if (ref >= 0) {
      deepest = std::max(deepest, WorstStack(f, ref, top));
    } else if (top) {
      const Instance& inst = f.instances[RtLeafFirst(ref)];
      if (inst.kind != RT_INSTANCE_SPHERE)
        deepest = std::max(deepest, 1 + WorstStack(f, inst.blas_root, false));
    }
  }
  return std::max(children - 1, 0) + deepest;
}

SceneDesc SoupScene(int triangles, int objects, std::mt19937& rng) {
  SceneDesc s = BaseScene();
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<Vec3d> p;
  std::vector<std::array<int, 3>> t;
  for (int i = 0; i < triangles; ++i) {
    Vec3d c{u(rng), u(rng), u(rng)};
    for (int k = 0; k < 3; ++k) p.push_back(c + Vec3d{u(rng), u(rng), u(rng)} * 0.05);
    t.push_back({3 * i, 3 * i + 1, 3 * i + 2});
  }
  int mesh = AddMesh(s, p, t);
  for (int k = 0; k < objects; ++k) {
    Mat4 m = Mat4::translation({3.0 * u(rng), 3.0 * u(rng), 3.0 * u(rng)});
    if (k % 3 == 1) m = m * Mat4::rotation(37.0 * k, {1, 2, 3});
    if (k % 4 == 2)
      AddSphere(s, m);
    else
      AddMeshObject(s, mesh, m);
  }
  return s;
}

// The bound holds for every tree shape tried, leaves of one triangle (the deepest trees)
// and of several, one object or many, and the kernel's bucket holds it.
TEST(KernelConfig, BvhStackBoundHoldsForTheFlattenedTrees) {
  std::mt19937 rng(795);
  int tightest = 0;
  for (int triangles : {1, 7, 300, 5000})
    for (int objects : {1, 2, 40, 300})
      for (int max_leaf : {1, 4}) {
        FlatScene f = Flatten(SoupScene(triangles, objects, rng), 16, max_leaf);
        const int needed =
            RT_BVH_STACK_NEEDED(RT_BVH_WIDTH, f.stats.tlas_depth + 1, f.stats.max_blas_depth + 1);
        const int worst = WorstStack(f, f.header.tlas_root, true);
        EXPECT_LE(worst, needed) << triangles << " triangles, " << objects << " objects, depth top "
                                 << f.stats.tlas_depth << " / mesh " << f.stats.max_blas_depth;
        EXPECT_GE(sized_for_scene(KernelConfig{}, f).bvh_stack, needed);
        tightest = std::max(tightest, worst * 100 / needed);
      }
  // The bound is not loose by far: some tree comes within two thirds of it.
  EXPECT_GE(tightest, 66);
}

TEST(KernelConfig, BvhStackBucketsAreMultiplesOf16FromThirtyTwo) {
  EXPECT_EQ(bvh_stack_bucket(1), 32);
  EXPECT_EQ(bvh_stack_bucket(25), 32);
  EXPECT_EQ(bvh_stack_bucket(32), 32);
  EXPECT_EQ(bvh_stack_bucket(33), 48);
  EXPECT_EQ(bvh_stack_bucket(49), 64);
}

TEST(KernelConfig, SizesTheArraysAndRefusesTreesDeeperThanTheTraversal) {
  FlatScene f;
  f.header.max_depth = 6;
  f.stats.tlas_depth = 0;
  f.stats.max_blas_depth = 6;
  KernelConfig k = sized_for_scene(KernelConfig{}, f);
  EXPECT_EQ(k.bvh_stack, 32);  // 3 * (1 + 7) + 1 = 25 entries for 4-wide nodes.
  EXPECT_EQ(k.ray_tree_depth, 6);
  EXPECT_EQ(kernel_defines(0x16, k),
            "-cl-std=CL1.2 -DRT_KERNEL_FEATURES=22 -DRT_BVH_WIDTH=4 -DRT_BVH_STACK=32 "
            "-DRT_RAY_TREE_DEPTH=6");
  // Without sizes the kernel keeps its static bounds.
  EXPECT_EQ(kernel_defines(0x16, KernelConfig{}),
            "-cl-std=CL1.2 -DRT_KERNEL_FEATURES=22 -DRT_BVH_WIDTH=4");
  f.stats.tlas_depth = f.stats.max_blas_depth = RT_BVH_MAX_DEPTH;
  try {
    sized_for_scene(KernelConfig{}, f);
    ADD_FAILURE() << "a tree deeper than the traversal's stack was accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("BVH too deep"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace rt
