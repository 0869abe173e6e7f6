// BVH construction (bvh_build.h): every box lies in its leaf's bounds, each primitive once,
// for random boxes and degenerate inputs (one point, a line, empty).
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "bvh/bvh_build.h"
#include "support/geometry_harness.h"

namespace rt {
namespace {

using namespace test;

bool Contains(const BinaryBvhNode& n, const Aabb& b) {
  for (int k = 0; k < 3; ++k)
    if (b.lo[k] < n.lo[k] || b.hi[k] > n.hi[k]) return false;
  return true;
}

bool Contains(const BinaryBvhNode& n, const BinaryBvhNode& c) {
  for (int k = 0; k < 3; ++k)
    if (c.lo[k] < n.lo[k] || c.hi[k] > n.hi[k]) return false;
  return true;
}

void ValidateBvh(const std::vector<Aabb>& boxes, const std::vector<BinaryBvhNode>& nodes,
                 size_t first_node, const BvhBuildResult& r, const std::vector<int>& order,
                 int prim_offset, int max_leaf) {
  const int n = static_cast<int>(boxes.size());
  ASSERT_EQ(static_cast<int>(order.size()), n);
  std::vector<int> sorted = order;
  std::sort(sorted.begin(), sorted.end());
  for (int i = 0; i < n; ++i) ASSERT_EQ(sorted[i], i) << "order is not a permutation";
  ASSERT_EQ(r.root, static_cast<int>(first_node));
  std::vector<int> covered(n, 0), visits(nodes.size(), 0);
  std::vector<std::pair<int, int>> stack = {{r.root, 0}};
  int max_depth = 0;
  while (!stack.empty()) {
    auto [index, depth] = stack.back();
    stack.pop_back();
    ASSERT_GE(index, static_cast<int>(first_node));
    ASSERT_LT(index, static_cast<int>(nodes.size()));
    ASSERT_EQ(++visits[index], 1) << "node reached twice";
    max_depth = std::max(max_depth, depth);
    const BinaryBvhNode& node = nodes[index];
    if (node.count > 0) {
      ASSERT_LE(node.count, std::max(1, max_leaf));
      int begin = node.first - prim_offset;
      ASSERT_GE(begin, 0);
      ASSERT_LE(begin + node.count, n);
      for (int j = begin; j < begin + node.count; ++j) {
        ++covered[j];
        ASSERT_TRUE(Contains(node, boxes[order[j]])) << "leaf " << index << " prim " << order[j];
      }
    } else {
      ASSERT_LE(-node.count, 2) << "split axis";
      ASSERT_GT(node.first, index);
      ASSERT_LT(node.first + 1, static_cast<int>(nodes.size()));
      ASSERT_TRUE(Contains(node, nodes[node.first])) << "node " << index;
      ASSERT_TRUE(Contains(node, nodes[node.first + 1])) << "node " << index;
      stack.push_back({node.first, depth + 1});
      stack.push_back({node.first + 1, depth + 1});
    }
  }
  for (int i = 0; i < n; ++i) ASSERT_EQ(covered[i], 1) << "position " << i;
  for (size_t i = first_node; i < nodes.size(); ++i) EXPECT_EQ(visits[i], 1) << "orphan " << i;
  EXPECT_EQ(r.depth, max_depth);
  EXPECT_LE(max_depth, RT_BVH_MAX_DEPTH);
}

Aabb RandomBox(std::mt19937& rng, double spread, double max_size) {
  std::uniform_real_distribution<double> u(-spread, spread), sz(0, max_size);
  Aabb b;
  double c[3] = {u(rng), u(rng), u(rng)};
  b.grow(static_cast<float>(c[0]), static_cast<float>(c[1]), static_cast<float>(c[2]));
  b.grow(static_cast<float>(c[0] + sz(rng)), static_cast<float>(c[1] + sz(rng)),
         static_cast<float>(c[2] + sz(rng)));
  return b;
}

TEST(GeometryBvhBuild, RandomBoxesGiveAValidTree) {
  std::mt19937 rng(1);
  for (int count : {1, 2, 3, 17, 1000})
    for (int bins : {2, 16, 64})
      for (int max_leaf : {1, 4, 16}) {
        SCOPED_TRACE("count " + std::to_string(count) + " bins " + std::to_string(bins) +
                     " max_leaf " + std::to_string(max_leaf));
        std::vector<Aabb> boxes;
        for (int i = 0; i < count; ++i) boxes.push_back(RandomBox(rng, 10, i % 7 == 0 ? 8 : 1));
        // Existing nodes and a primitive offset, as for the second mesh of a scene.
        std::vector<BinaryBvhNode> nodes(5);
        std::vector<int> order;
        BvhOptions opt;
        opt.bins = bins;
        opt.max_leaf = max_leaf;
        BvhBuildResult r = build_bvh(boxes, opt, max_leaf, 123, nodes, order);
        ValidateBvh(boxes, nodes, 5, r, order, 123, max_leaf);
      }
}

TEST(GeometryBvhBuild, DegenerateInputsStillGiveAValidTree) {
  for (int max_leaf : {1, 4}) {
    BvhOptions opt;
    opt.max_leaf = max_leaf;
    // Identical boxes: no split separates the centroids (object-median fallback).
    std::vector<Aabb> same(300);
    for (auto& b : same) b.grow(1, 2, 3), b.grow(2, 3, 4);
    std::vector<BinaryBvhNode> nodes;
    std::vector<int> order;
    BvhBuildResult r = build_bvh(same, opt, max_leaf, 0, nodes, order);
    ValidateBvh(same, nodes, 0, r, order, 0, max_leaf);
    // Flat boxes on a line, and points.
    std::vector<Aabb> line(257);
    for (size_t i = 0; i < line.size(); ++i) line[i].grow(static_cast<float>(i % 13), 0, 0);
    nodes.clear();
    r = build_bvh(line, opt, max_leaf, 0, nodes, order);
    ValidateBvh(line, nodes, 0, r, order, 0, max_leaf);
  }
  std::vector<BinaryBvhNode> nodes;
  std::vector<int> order;
  EXPECT_EQ(build_bvh({}, BvhOptions{}, 4, 0, nodes, order).root, -1);
  EXPECT_TRUE(nodes.empty());
}

}  // namespace
}  // namespace rt
