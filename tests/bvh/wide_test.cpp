// The parallel BVH build and the wide collapse: the same tree whatever the thread count,
// and wide nodes, 4 and 8 children each, that cover every primitive exactly once inside
// their parents' boxes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <random>
#include <vector>

#include "bvh/bvh_build.h"
#include "bvh/bvh_wide.h"

namespace rt {
namespace {

std::vector<Aabb> RandomBoxes(int count, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(-100, 100), size(0, 2);
  std::vector<Aabb> boxes(count);
  for (auto& b : boxes) {
    float x = u(rng), y = u(rng), z = u(rng) * 0.01f;  // Mostly flat, like a terrain.
    b.grow(x, y, z);
    b.grow(x + size(rng), y + size(rng), z + size(rng));
  }
  return boxes;
}

TEST(BvhBuild, SameTreeForOneAndTwoThreads) {
  // Large enough for parallel binning of the top levels and many parallel subtrees.
  std::vector<Aabb> boxes = RandomBoxes(300000, 7);
  BvhOptions one, two;
  one.threads = 1;
  two.threads = 2;
  std::vector<BinaryBvhNode> a, b;
  std::vector<int> order_a, order_b;
  BvhBuildResult ra = build_bvh(boxes, one, 4, 0, a, order_a);
  BvhBuildResult rb = build_bvh(boxes, two, 4, 0, b, order_b);
  EXPECT_EQ(ra.root, rb.root);
  EXPECT_EQ(ra.depth, rb.depth);
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(BinaryBvhNode)), 0);
  EXPECT_EQ(order_a, order_b);
}

// With merge_leaves (the triangle levels), neighbouring leaves that fit one block become
// one: leaves then hold up to `width` primitives, still each primitive once, and at width 8
// a tree built with leaves of at most 4 fills its blocks far better.
TEST(BvhWide, CollapseCoversEveryPrimitiveOnceInsideItsBoxes) {
  for (int width : {4, 8}) {
    if (!valid_bvh_width(width)) continue;  // A build of RT_BVH_WIDTH=8 makes 8 only.
    double leaves_unmerged = 0;
    for (bool merge : {false, true})
      for (int count : {1, 3, 5, 1000, 40000}) {
        SCOPED_TRACE("width " + std::to_string(width) + " merge " + std::to_string(merge) +
                     " count " + std::to_string(count));
        std::vector<Aabb> boxes = RandomBoxes(count, count);
        std::vector<BinaryBvhNode> binary;
        std::vector<int> order;
        BvhBuildResult r = build_bvh(boxes, BvhOptions{}, 4, 10, binary, order);
        PageAlignedVector<BvhNode> storage(2 * wide_units(width));  // Nodes of an earlier mesh.
        WideNodes wide(storage, width);
        WideBvhResult w = collapse_bvh(binary, r.root, wide, merge);
        ASSERT_EQ(w.root, 2);
        EXPECT_LE(w.depth, r.depth);
        std::vector<int> covered(count, 0), visits(wide.size(), 0);
        std::vector<int> stack = {w.root};
        int most_children = 0, leaves = 0;
        while (!stack.empty()) {
          int index = stack.back();
          stack.pop_back();
          ASSERT_EQ(++visits[index], 1) << "node reached twice";
          int children = 0;
          for (int lane = 0; lane < width; ++lane) {
            int child = wide.child(index, lane);
            if (child == RT_BVH_EMPTY) continue;
            ++children;
            float lo[3], hi[3];
            for (int k = 0; k < 3; ++k)
              lo[k] = wide.bound(index, k, lane), hi[k] = wide.bound(index, 3 + k, lane);
            if (child >= 0) {
              ASSERT_GT(child, index);
              ASSERT_LT(child, static_cast<int>(wide.size()));
              for (int l = 0; l < width; ++l) {
                if (wide.child(child, l) == RT_BVH_EMPTY) continue;
                for (int k = 0; k < 3; ++k) {
                  EXPECT_LE(lo[k], wide.bound(child, k, l));
                  EXPECT_GE(hi[k], wide.bound(child, 3 + k, l));
                }
              }
              stack.push_back(child);
              continue;
            }
            int first = RtLeafFirst(child) - 10, n_prims = RtLeafCount(child);
            ASSERT_GE(first, 0);
            ASSERT_LE(first + n_prims, count);
            EXPECT_LE(n_prims, merge ? width : 4);
            ++leaves;
            for (int i = first; i < first + n_prims; ++i) {
              ++covered[i];
              const Aabb& b = boxes[order[i]];
              for (int k = 0; k < 3; ++k) EXPECT_TRUE(lo[k] <= b.lo[k] && b.hi[k] <= hi[k]);
            }
          }
          most_children = std::max(most_children, children);
        }
        for (int i = 0; i < count; ++i) ASSERT_EQ(covered[i], 1) << "position " << i;
        for (size_t i = 2; i < wide.size(); ++i) EXPECT_EQ(visits[i], 1) << "orphan " << i;
        if (count >= 1000) {
          EXPECT_EQ(most_children, width);  // Nodes fill up to the width.
        }
        if (count == 40000 && !merge) leaves_unmerged = leaves;
        // Leaves of 1-4 primitives: merged at width 8, at least a third fewer.
        if (count == 40000 && merge && width == 8) {
          std::printf("[ width 8 ] %d leaves merged, %.0f not\n", leaves, leaves_unmerged);
          EXPECT_LT(leaves, 2 * leaves_unmerged / 3);
        }
      }
  }
}

}  // namespace
}  // namespace rt
