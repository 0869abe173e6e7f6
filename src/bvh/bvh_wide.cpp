#include "bvh_wide.h"

#include "bvh_lanes.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace rt {

namespace {

float area(const BinaryBvhNode& n) {
  float dx = n.hi[0] - n.lo[0], dy = n.hi[1] - n.lo[1], dz = n.hi[2] - n.lo[2];
  return 2.0f * (dx * dy + dy * dz + dz * dx);
}

class Collapser {
 public:
  Collapser(const std::vector<BinaryBvhNode>& binary, WideNodes wide, bool merge_leaves)
      : bin_(binary), wide_(wide), width_(wide.width()), merge_leaves_(merge_leaves) {}

  // Emits the wide node whose children are the binary nodes below `node` that the greedy
  // rule picks, and returns its index.
  int emit(const BinaryBvhNode& node, int depth) {
    depth_ = std::max(depth_, depth);
    // The children: open the interior child of largest surface area until the node is
    // full (Wald, Benthin and Boulos 2008), so big boxes are tested early, as one group.
    // They are copies, so that two leaves can be made one.
    BinaryBvhNode kids[kMaxBvhWidth];
    int n = 0;
    if (node.count > 0) {
      kids[n++] = node;
    } else {
      kids[n++] = bin_[node.first];
      kids[n++] = bin_[node.first + 1];
    }
    do {
      while (n < width_) {
        int best = -1;
        float best_area = -1;
        for (int i = 0; i < n; ++i)
          if (kids[i].count <= 0 && area(kids[i]) > best_area) best = i, best_area = area(kids[i]);
        if (best < 0) break;
        // The opened node's two children take its slot and the next free one, in order.
        int first = kids[best].first;
        for (int i = n; i > best + 1; --i) kids[i] = kids[i - 1];
        kids[best] = bin_[first];
        kids[best + 1] = bin_[first + 1];
        ++n;
      }
    } while (merge_leaves_ && merge_two_leaves(kids, &n));
    const size_t index = wide_.append();
    for (int lane = 0; lane < width_; ++lane) {
      int ref = RT_BVH_EMPTY;
      // An empty lane's box is inverted to infinity: every ray enters it at +inf and
      // leaves at -inf, whatever its direction's signs, so the node test never picks it.
      for (int k = 0; k < 3; ++k) {
        wide_.set_bound(index, k, lane, INFINITY);
        wide_.set_bound(index, 3 + k, lane, -INFINITY);
      }
      if (lane < n) {
        const BinaryBvhNode& c = kids[lane];
        for (int k = 0; k < 3; ++k) {
          wide_.set_bound(index, k, lane, c.lo[k]);
          wide_.set_bound(index, 3 + k, lane, c.hi[k]);
        }
        ref = c.count > 0 ? leaf_ref(c) : emit(c, depth + 1);
      }
      wide_.set_child(index, lane, ref);
    }
    return static_cast<int>(index);
  }

  int depth() const { return depth_; }

 private:
  // Makes the first two neighbouring leaves whose triangles fit one block of the node's
  // width one leaf of both (children are in the binary tree's order, so neighbouring
  // leaves hold neighbouring primitive ranges). Returns whether it did, freeing a lane.
  bool merge_two_leaves(BinaryBvhNode* kids, int* n) const {
    for (int i = 0; i + 1 < *n; ++i) {
      BinaryBvhNode &a = kids[i], &b = kids[i + 1];
      if (a.count <= 0 || b.count <= 0 || a.count + b.count > width_ ||
          a.first + a.count != b.first)
        continue;
      for (int k = 0; k < 3; ++k) {
        a.lo[k] = std::min(a.lo[k], b.lo[k]);
        a.hi[k] = std::max(a.hi[k], b.hi[k]);
      }
      a.count += b.count;
      for (int j = i + 1; j + 1 < *n; ++j) kids[j] = kids[j + 1];
      --*n;
      return true;
    }
    return false;
  }

  static int leaf_ref(const BinaryBvhNode& c) {
    if (c.count > RT_BVH_MAX_LEAF || c.first + c.count > RT_BVH_MAX_PRIMITIVES)
      throw std::length_error("BVH: " + std::to_string(c.first + c.count) +
                              " primitives or a leaf of " + std::to_string(c.count) +
                              " exceed the node format's limits");
    return RtLeafRef(c.first, c.count);
  }

  const std::vector<BinaryBvhNode>& bin_;
  WideNodes wide_;
  int width_;
  bool merge_leaves_;
  int depth_ = 0;
};

}  // namespace

WideBvhResult collapse_bvh(const std::vector<BinaryBvhNode>& binary, int root, WideNodes wide,
                           bool merge_leaves) {
  WideBvhResult r;
  if (root < 0) return r;
  Collapser c(binary, wide, merge_leaves);
  r.root = c.emit(binary[root], 0);
  r.depth = c.depth();
  return r;
}

}  // namespace rt
