#include "bvh_build.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "cl/bvh.h"

namespace rt {

void Aabb::grow(const Aabb& b) {
  for (int k = 0; k < 3; ++k) {
    lo[k] = std::min(lo[k], b.lo[k]);
    hi[k] = std::max(hi[k], b.hi[k]);
  }
}

void Aabb::grow(float x, float y, float z) {
  float p[3] = {x, y, z};
  for (int k = 0; k < 3; ++k) {
    lo[k] = std::min(lo[k], p[k]);
    hi[k] = std::max(hi[k], p[k]);
  }
}

float Aabb::area() const {
  if (empty()) return 0;
  float dx = hi[0] - lo[0], dy = hi[1] - lo[1], dz = hi[2] - lo[2];
  return 2.0f * (dx * dy + dy * dz + dz * dx);
}

namespace {

// Past this depth splits fall back to the object median, which halves the count, so
// the depth stays below RT_BVH_MAX_DEPTH for up to 2^27 primitives per level.
constexpr int kMedianDepth = RT_BVH_MAX_DEPTH - 28;

class Builder {
 public:
  Builder(const std::vector<Aabb>& boxes, const BvhOptions& options, int max_leaf, int prim_offset,
          std::vector<BinaryBvhNode>& nodes, std::vector<int>& order)
      : boxes_(boxes),
        opt_(options),
        max_leaf_(max_leaf),
        offset_(prim_offset),
        nodes_(nodes),
        order_(order) {
    centroids_.resize(boxes.size() * 3);
    for (size_t i = 0; i < boxes.size(); ++i)
      for (int k = 0; k < 3; ++k) centroids_[i * 3 + k] = 0.5f * (boxes[i].lo[k] + boxes[i].hi[k]);
  }

  BvhBuildResult run() {
    BvhBuildResult r;
    order_.resize(boxes_.size());
    std::iota(order_.begin(), order_.end(), 0);
    r.root = static_cast<int>(nodes_.size());
    nodes_.emplace_back();
    build(r.root, 0, static_cast<int>(boxes_.size()), 0);
    r.depth = max_depth_;
    return r;
  }

 private:
  float centroid(int prim, int axis) const { return centroids_[prim * 3 + axis]; }

  void make_leaf(BinaryBvhNode& n, int begin, int end) {
    n.first = offset_ + begin;
    n.count = end - begin;
  }

  void build(int node_index, int begin, int end, int depth) {
    max_depth_ = std::max(max_depth_, depth);
    Aabb box, cbox;
    for (int i = begin; i < end; ++i) {
      box.grow(boxes_[order_[i]]);
      int p = order_[i];
      cbox.grow(centroid(p, 0), centroid(p, 1), centroid(p, 2));
    }
    BinaryBvhNode& n = nodes_[node_index];
    for (int k = 0; k < 3; ++k) {
      n.lo[k] = box.lo[k];
      n.hi[k] = box.hi[k];
    }
    int count = end - begin;
    if (count <= max_leaf_ && (count == 1 || max_leaf_ > 1)) {
      make_leaf(n, begin, end);
      return;
    }
    int axis = 0, mid = -1;
    if (depth < kMedianDepth) mid = sah_split(box, cbox, begin, end, &axis);
    if (mid == -2) {  // The SAH prefers a leaf.
      make_leaf(n, begin, end);
      return;
    }
    if (mid < 0) {
      // Object median along the widest centroid extent: always progresses.
      float best = -1;
      for (int k = 0; k < 3; ++k)
        if (cbox.hi[k] - cbox.lo[k] > best) best = cbox.hi[k] - cbox.lo[k], axis = k;
      mid = (begin + end) / 2;
      std::nth_element(order_.begin() + begin, order_.begin() + mid, order_.begin() + end,
                       [&](int a, int b) { return centroid(a, axis) < centroid(b, axis); });
    }
    int left = static_cast<int>(nodes_.size());
    nodes_.emplace_back();
    nodes_.emplace_back();
    nodes_[node_index].first = left;
    nodes_[node_index].count = -axis;
    build(left, begin, mid, depth + 1);
    build(left + 1, mid, end, depth + 1);
  }

  // Returns the partition point of the best binned-SAH split (and its axis), -2 when a
  // leaf is cheaper, or -1 when no split separates the centroids.
  int sah_split(const Aabb& box, const Aabb& cbox, int begin, int end, int* axis_out) {
    const int nb = std::max(2, opt_.bins);
    float best_cost = 3.4e38f;
    int best_axis = -1, best_bin = -1;
    std::vector<Aabb> bin_box(nb);
    std::vector<int> bin_count(nb);
    std::vector<float> right_area(nb);
    std::vector<int> right_count(nb);
    for (int axis = 0; axis < 3; ++axis) {
      float lo = cbox.lo[axis], extent = cbox.hi[axis] - lo;
      if (!(extent > 0)) continue;
      float scale = nb / extent;
      std::fill(bin_box.begin(), bin_box.end(), Aabb());
      std::fill(bin_count.begin(), bin_count.end(), 0);
      for (int i = begin; i < end; ++i) {
        int p = order_[i];
        int b = std::min(nb - 1, static_cast<int>((centroid(p, axis) - lo) * scale));
        bin_box[b].grow(boxes_[p]);
        ++bin_count[b];
      }
      Aabb acc;
      int cnt = 0;
      for (int b = nb - 1; b > 0; --b) {
        acc.grow(bin_box[b]);
        cnt += bin_count[b];
        right_area[b] = acc.area();
        right_count[b] = cnt;
      }
      acc = Aabb();
      cnt = 0;
      for (int b = 0; b < nb - 1; ++b) {
        acc.grow(bin_box[b]);
        cnt += bin_count[b];
        if (cnt == 0 || right_count[b + 1] == 0) continue;
        float cost = acc.area() * cnt + right_area[b + 1] * right_count[b + 1];
        if (cost < best_cost) best_cost = cost, best_axis = axis, best_bin = b;
      }
    }
    if (best_axis < 0) return -1;
    // Costs relative to intersecting every primitive: traversal step 1, intersection 1.
    float leaf_cost = static_cast<float>(end - begin);
    float split_cost = 1.0f + best_cost / std::max(box.area(), 1e-30f);
    if (end - begin <= max_leaf_ && split_cost >= leaf_cost) return -2;
    float lo = cbox.lo[best_axis], scale = nb / (cbox.hi[best_axis] - lo);
    auto mid = std::partition(order_.begin() + begin, order_.begin() + end, [&](int p) {
      return std::min(nb - 1, static_cast<int>((centroid(p, best_axis) - lo) * scale)) <= best_bin;
    });
    *axis_out = best_axis;
    return static_cast<int>(mid - order_.begin());
  }

  const std::vector<Aabb>& boxes_;
  const BvhOptions& opt_;
  int max_leaf_, offset_;
  std::vector<BinaryBvhNode>& nodes_;
  std::vector<int>& order_;
  std::vector<float> centroids_;
  int max_depth_ = 0;
};

}  // namespace

BvhBuildResult build_bvh(const std::vector<Aabb>& boxes, const BvhOptions& options, int max_leaf,
                         int prim_offset, std::vector<BinaryBvhNode>& nodes,
                         std::vector<int>& order) {
  if (boxes.empty()) return {};
  return Builder(boxes, options, max_leaf, prim_offset, nodes, order).run();
}

}  // namespace rt
