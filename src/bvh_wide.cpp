#include "bvh_wide.h"

#include "bvh_lanes.h"

#include <cmath>
#include <cstring>
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
  Collapser(const std::vector<BinaryBvhNode>& binary, PageAlignedVector<BvhNode>& wide)
      : bin_(binary), wide_(wide) {}

  // Emits the wide node whose children are the binary nodes below `b` that the greedy
  // rule picks, and returns its index.
  int emit(int b, int depth) {
    depth_ = std::max(depth_, depth);
    // The children: open the interior child of largest surface area until the node is
    // full (Wald, Benthin and Boulos 2008), so big boxes are tested early, as one group.
    int kids[RT_BVH_WIDTH];
    int n = 0;
    if (bin_[b].count > 0) {
      kids[n++] = b;
    } else {
      kids[n++] = bin_[b].first;
      kids[n++] = bin_[b].first + 1;
    }
    while (n < RT_BVH_WIDTH) {
      int best = -1;
      float best_area = -1;
      for (int i = 0; i < n; ++i)
        if (bin_[kids[i]].count <= 0 && area(bin_[kids[i]]) > best_area)
          best = i, best_area = area(bin_[kids[i]]);
      if (best < 0) break;
      // The opened node's two children take its slot and the next free one, in order.
      int first = bin_[kids[best]].first;
      for (int i = n; i > best + 1; --i) kids[i] = kids[i - 1];
      kids[best] = first;
      kids[best + 1] = first + 1;
      ++n;
    }
    int index = static_cast<int>(wide_.size());
    wide_.emplace_back();
    BvhNode node;
    std::memset(&node, 0, sizeof node);
    for (int lane = 0; lane < RT_BVH_WIDTH; ++lane) {
      int ref = RT_BVH_EMPTY;
      // An empty lane's box is inverted to infinity: every ray enters it at +inf and
      // leaves at -inf, whatever its direction's signs, so the node test never picks it.
      for (int k = 0; k < 3; ++k) {
        set_lane(node.bounds[k], lane, INFINITY);
        set_lane(node.bounds[3 + k], lane, -INFINITY);
      }
      if (lane < n) {
        const BinaryBvhNode& c = bin_[kids[lane]];
        for (int k = 0; k < 3; ++k) {
          set_lane(node.bounds[k], lane, c.lo[k]);
          set_lane(node.bounds[3 + k], lane, c.hi[k]);
        }
        ref = c.count > 0 ? leaf_ref(c) : emit(kids[lane], depth + 1);
      }
      set_lane(node.child, lane, ref);
    }
    wide_[index] = node;
    return index;
  }

  int depth() const { return depth_; }

 private:
  static int leaf_ref(const BinaryBvhNode& c) {
    if (c.count > RT_BVH_MAX_LEAF || c.first + c.count > RT_BVH_MAX_PRIMITIVES)
      throw std::length_error("BVH: " + std::to_string(c.first + c.count) +
                              " primitives or a leaf of " + std::to_string(c.count) +
                              " exceed the node format's limits");
    return RtLeafRef(c.first, c.count);
  }

  const std::vector<BinaryBvhNode>& bin_;
  PageAlignedVector<BvhNode>& wide_;
  int depth_ = 0;
};

}  // namespace

WideBvhResult collapse_bvh(const std::vector<BinaryBvhNode>& binary, int root,
                           PageAlignedVector<BvhNode>& wide) {
  WideBvhResult r;
  if (root < 0) return r;
  Collapser c(binary, wide);
  r.root = c.emit(root, 0);
  r.depth = c.depth();
  return r;
}

}  // namespace rt
